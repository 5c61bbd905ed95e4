// candela._candela: the C++ side of the Python module (docs/python.md). Thin: each function
// converts its arguments, calls the study layer as the command line does (study/run_case.h,
// study/points_study.h, photometry/) and converts the result to Python objects. The public API,
// its classes and the result arrays are built on these in python/candela/__init__.py.
#include "python/interruptible.h"

#include "base/error.h"
#include "base/units.h"
#include "base/warning.h"
#include "engine/daylight.h"
#include "engine/radiance/reader.h"
#include "engine/scene.h"
#include "engine/trace_settings.h"
#include "photometry/luminaire_summary.h"
#include "photometry/photometric_file.h"
#include "photometry/site.h"
#include "photometry/sky_type.h"
#include "photometry/sun_spa.h"
#include "reports/report_data.h"
#include "study/case/case_file.h"
#include "study/points_study.h"
#include "study/run_case.h"
#include "study/grids/sensor_grid.h"
#include "study/trace_options.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace candela::python {

namespace {

const FileLoc kPython{"python", 0, 0};

py::list warningList(const std::vector<Warning>& warnings) {
  py::list out;
  for (const Warning& w : warnings) {
    py::dict d;
    d["code"] = w.code;
    d["message"] = w.message;
    d["file"] = w.loc.file;
    d["line"] = w.loc.line;
    d["text"] = warningLine(w);
    out.append(d);
  }
  return out;
}

TraceOverrides traceOverrides(const std::optional<std::string>& quality, const std::optional<int>& threads,
                              const std::optional<uint64_t>& seed, const std::optional<std::string>& method) {
  TraceOverrides t;
  if (quality) t.quality = parseQuality(*quality);
  if (threads) {
    if (*threads < 0 || *threads > 4096) throw InputError(kPython, "threads must be in [0, 4096] (0 = all cores)");
    t.threads = *threads;
  }
  t.seed = seed;
  if (method) t.method = parseMethod(*method);
  return t;
}

template <class T>
std::optional<T> optionalItem(const py::dict& d, const char* key) {
  if (!d.contains(key) || d[key].is_none()) return std::nullopt;
  return d[key].cast<T>();
}

// A candela.Sky's fields (python/candela/__init__.py) as the command line's --sky options give them.
DaylightSpec daylightFromDict(const py::dict& d) {
  DaylightSpec s;
  std::string why;
  const std::string typeName = d["type"].cast<std::string>();
  const std::optional<SkyType> type = parseSkyType(typeName, &why);
  if (!type) throw InputError(kPython, why);
  if (type->kind == SkyKind::kAnnual)
    throw InputError(kPython, "an annual sky is a whole year: run an annual case (candela.load_case)");
  s.skyType = *type;
  s.skyLoc = kPython;
  s.timeLoc = kPython;
  s.sunAltitudeDeg = optionalItem<double>(d, "sun_altitude");
  s.sunAzimuthDeg = optionalItem<double>(d, "sun_azimuth");
  s.latitudeDeg = optionalItem<double>(d, "latitude");
  s.longitudeDeg = optionalItem<double>(d, "longitude");
  s.elevationM = optionalItem<double>(d, "elevation").value_or(0.0);
  s.timezoneHours = optionalItem<double>(d, "timezone").value_or(0.0);
  s.northDeg = optionalItem<double>(d, "north").value_or(0.0);
  s.time = optionalItem<std::string>(d, "time").value_or("");
  s.sun = optionalItem<bool>(d, "sun").value_or(true);
  s.diffuseHorizontalLux = optionalItem<double>(d, "diffuse_horizontal_illuminance");
  s.directNormalLux = optionalItem<double>(d, "direct_normal_illuminance");
  s.directNormalWm2 = optionalItem<double>(d, "direct_normal_irradiance");
  s.diffuseHorizontalWm2 = optionalItem<double>(d, "diffuse_horizontal_irradiance");
  s.groundReflectance = optionalItem<double>(d, "ground_reflectance").value_or(0.2);
  return s;
}

LuminairePlacement placementFromDict(const py::dict& d, int index) {
  LuminairePlacement p;
  p.file = d["file"].cast<std::string>();
  p.name = optionalItem<std::string>(d, "name").value_or("luminaire" + std::to_string(index + 1));
  const auto vec = [&](const char* key, Vec3 fallback) {
    const std::optional<std::vector<double>> v = optionalItem<std::vector<double>>(d, key);
    if (!v) return fallback;
    if (v->size() != 3) throw InputError(kPython, std::string("luminaire ") + key + " needs 3 numbers");
    return Vec3((*v)[0], (*v)[1], (*v)[2]);
  };
  p.positionM = vec("position", Vec3(0.0));
  p.aim = vec("aim", Vec3(0.0, 0.0, -1.0));
  p.spinDeg = optionalItem<double>(d, "spin").value_or(0.0);
  p.multiplier = optionalItem<double>(d, "multiplier").value_or(1.0);
  p.maintenanceFactor = optionalItem<double>(d, "maintenance_factor").value_or(1.0);
  for (double v : {p.positionM.x, p.positionM.y, p.positionM.z, p.aim.x, p.aim.y, p.aim.z, p.spinDeg, p.multiplier})
    if (!std::isfinite(v)) throw InputError(kPython, "a luminaire's numbers must be finite");
  // As a case file's numbers (study/case/case_toml.cpp): positions within 1e7 m, and no multiplier
  // or spin near the overflow of the intensities (multiplier=1e308 once ended as an internal error).
  for (double v : {p.positionM.x, p.positionM.y, p.positionM.z})
    if (std::abs(v) > kMaxCoordinateM)
      throw InputError(kPython, "a luminaire's position lies beyond 1e7 m from the origin (" + compactNumber(v) + ")");
  for (double v : {p.spinDeg, p.multiplier})
    if (std::abs(v) > kMaxCoordinateM)
      throw InputError(kPython, "a luminaire's spin and multiplier must lie within ±1e7, got " + compactNumber(v));
  if (p.aim == Vec3(0.0)) throw InputError(kPython, "a luminaire's aim must not be zero");
  const std::optional<Vec3> aim = unitDirection(p.aim);
  if (!aim) throw InputError(kPython, "a luminaire's aim cannot be normalised: its length overflows or underflows");
  p.aim = *aim;
  if (!(p.multiplier >= 0.0)) throw InputError(kPython, "a luminaire's multiplier must be >= 0");
  if (!(p.maintenanceFactor > 0.0 && p.maintenanceFactor <= 1.0))
    throw InputError(kPython, "a luminaire's maintenance_factor must be in (0, 1]");
  p.entry = index;
  p.loc = kPython;
  return p;
}

py::dict loadCase(const std::string& path) {
  const CaseFile c = readCaseFile(path);
  py::dict d;
  d["name"] = c.name;
  d["description"] = c.description;
  d["path"] = c.path.string();
  d["annual"] = c.sky.type.kind == SkyKind::kAnnual;
  d["out_dir"] = c.output.dir.string();
  py::list grids;
  for (const GridSpec& g : c.grids) grids.append(g.name);
  d["grids"] = grids;
  return d;
}

py::dict runCaseFile(const std::string& path, const std::optional<std::string>& out,
                     const std::optional<std::string>& quality, const std::optional<int>& threads,
                     const std::optional<uint64_t>& seed, bool strict, const py::object& progress) {
  RunRequest request;
  if (out) request.outDir = *out;
  request.trace = traceOverrides(quality, threads, seed, std::nullopt);
  request.strict = strict;
  const std::function<RunResult(StudyObserver&)> work = [&](StudyObserver& o) { return runCase(path, request, o); };
  const RunResult r = runInterruptible(work, progress);
  py::dict d;
  d["out_dir"] = r.outDir.string();
  d["annual"] = r.annual;
  d["hours"] = r.hours;
  d["warnings"] = warningList(r.data.warnings);
  return d;
}

py::dict checkScene(const std::vector<std::string>& files) {
  Scene scene;
  readSceneFiles(std::vector<std::filesystem::path>(files.begin(), files.end()), scene,
                 sceneReadOptions(nullptr, TraceOverrides{}));
  py::dict d;
  d["luminaires"] = scene.luminaires.size();
  return d;
}

py::tuple illuminance(const std::vector<std::string>& files, const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
                      const std::optional<py::dict>& sky, const std::vector<py::dict>& luminaires,
                      const std::optional<std::string>& quality, uint64_t seed, int threads,
                      const std::optional<std::string>& method, bool strict, const py::object& progress) {
  if (points.ndim() != 2 || points.shape(1) != 6)
    throw InputError(FileLoc{"points", 0, 0}, "points must be an (N, 6) array of x y z dx dy dz");
  std::vector<SensorPoint> sensors;
  sensors.reserve(static_cast<std::size_t>(points.shape(0)));
  const auto p = points.unchecked<2>();
  for (py::ssize_t i = 0; i < points.shape(0); ++i) {
    const double v[6] = {p(i, 0), p(i, 1), p(i, 2), p(i, 3), p(i, 4), p(i, 5)};
    // Row i + 1, as the line of a points file: errors name the row.
    sensors.push_back(checkedSensorPoint(v, FileLoc{"points", static_cast<int>(i + 1), 0}));
  }
  PointsJob job;
  job.scenes.assign(files.begin(), files.end());
  if (sky) {
    const DaylightSpec spec = daylightFromDict(*sky);
    job.sky = [spec](DaylightSpec) { return spec; };
  }
  for (std::size_t i = 0; i < luminaires.size(); ++i) job.luminaires.push_back(placementFromDict(luminaires[i], int(i)));
  job.trace = traceOverrides(quality, threads, seed, method);
  job.strict = strict;
  job.pointsName = "points";
  const std::function<PointsResult(StudyObserver&)> work = [&](StudyObserver& o) {
    const PointsScene scene = loadPointsScene(job);
    return computePoints(scene, job.accelerator, sensors, o);
  };
  const PointsResult r = runInterruptible(work, progress);
  py::array_t<double> lux(static_cast<py::ssize_t>(sensors.size()));
  py::array_t<double> error(static_cast<py::ssize_t>(sensors.size()));
  auto l = lux.mutable_unchecked<1>();
  auto e = error.mutable_unchecked<1>();
  for (std::size_t i = 0; i < r.estimates.size(); ++i) {
    l(py::ssize_t(i)) = r.estimates[i].illuminanceLux();
    e(py::ssize_t(i)) = r.estimates[i].standardErrorLux();
  }
  return py::make_tuple(lux, error, warningList(r.warnings));
}

py::dict readLuminaire(const std::string& path) {
  const PhotometricWeb web = readPhotometricFile(path);
  const LuminaireSummary s = summarizeLuminaire(web);
  py::dict d;
  d["file"] = path;
  d["format"] = s.format;
  d["luminaire"] = s.luminaire;
  d["manufacturer"] = s.manufacturer;
  d["photometric_type"] = s.type == PhotometricType::kC ? "C" : "B";
  d["total_lumens"] = s.totalLumens;
  d["lamp_lumens"] = s.lampLumens > 0.0 ? py::object(py::float_(s.lampLumens)) : py::none();
  d["light_output_ratio"] = std::isnan(s.lightOutputRatio) ? py::none() : py::object(py::float_(s.lightOutputRatio));
  d["max_intensity_cd"] = s.maxIntensityCd;
  d["max_intensity_c_deg"] = s.maxDirection.cDeg;
  d["max_intensity_gamma_deg"] = s.maxDirection.gammaDeg;
  d["beam_angle_c0_deg"] = s.beamC0Deg;
  d["beam_angle_c90_deg"] = s.beamC90Deg;
  d["field_angle_c0_deg"] = s.fieldC0Deg;
  d["field_angle_c90_deg"] = s.fieldC90Deg;
  d["zonal_lumens"] = s.zonalLumens;
  d["downward_lumens"] = s.downwardLumens;
  d["upward_lumens"] = s.upwardLumens;
  d["input_watts"] = s.inputWatts > 0.0 ? py::object(py::float_(s.inputWatts)) : py::none();
  d["efficacy_lm_per_w"] = std::isnan(s.efficacyLmPerW) ? py::none() : py::object(py::float_(s.efficacyLmPerW));
  d["opening_m"] = py::make_tuple(s.openingWidthM, s.openingLengthM, s.openingHeightM);
  d["plane_angles_deg"] = py::array_t<double>(py::ssize_t(web.planeAnglesDeg().size()), web.planeAnglesDeg().data());
  d["polar_angles_deg"] = py::array_t<double>(py::ssize_t(web.polarAnglesDeg().size()), web.polarAnglesDeg().data());
  py::array_t<double> cd({py::ssize_t(web.planeAnglesDeg().size()), py::ssize_t(web.polarAnglesDeg().size())});
  auto c = cd.mutable_unchecked<2>();
  for (std::size_t i = 0; i < web.planeAnglesDeg().size(); ++i)
    for (std::size_t j = 0; j < web.polarAnglesDeg().size(); ++j) c(py::ssize_t(i), py::ssize_t(j)) = web.gridCd(i, j);
  d["intensity_cd"] = cd;
  return d;
}

py::dict sunPosition(double latitudeDeg, double longitudeDeg, double timezoneHours, double elevationM,
                     const std::string& time) {
  const FileLoc where{"sun_position", 0, 0};
  if (!(std::abs(latitudeDeg) <= 90.0)) throw InputError(where, "latitude must be in [-90, 90] degrees");
  if (!(std::abs(longitudeDeg) <= 180.0)) throw InputError(where, "longitude must be in [-180, 180] degrees");
  const LocalTime t = parseLocalTime(time, where);
  SpaInput in;
  in.latitudeDeg = latitudeDeg;
  in.longitudeDeg = longitudeDeg;
  in.elevationM = elevationM;
  // An offset written in the time is the time zone of that clock reading; else the site's.
  in.timezoneHours = t.utcOffsetHours.value_or(timezoneHours);
  if (!(std::abs(in.timezoneHours) <= 18.0)) throw InputError(where, "timezone must be in [-18, 18] hours");
  in.year = t.year;
  in.month = t.month;
  in.day = t.day;
  in.hourOfDay = t.hourOfDay();
  in.deltaTSec = estimateDeltaTSec(t.year + (t.dayOfYear() - 0.5) / 365.25);
  SpaResult r;
  try {
    r = computeSunPosition(in);
  } catch (const InputError& e) {
    throw InputError(where, e.message());
  }
  py::dict d;
  d["altitude_deg"] = r.altitudeDeg;
  d["azimuth_deg"] = r.azimuthDeg;
  d["zenith_deg"] = r.zenithDeg;
  d["sunrise_hour"] = r.sunriseHour;
  d["transit_hour"] = r.transitHour;
  d["sunset_hour"] = r.sunsetHour;
  return d;
}

}  // namespace

}  // namespace candela::python

PYBIND11_MODULE(_candela, m) {
  using namespace candela;
  using namespace candela::python;
  m.doc() = "candela's engine; use the package `candela` (docs/python.md)";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      const py::object cls = py::module_::import("candela.errors").attr("InputError");
      const py::object err = cls(e.what(), e.loc().file, e.loc().line, e.message());
      PyErr_SetObject(cls.ptr(), err.ptr());
    }
  });
  m.def("load_case", &loadCase, py::arg("path"));
  m.def("run_case", &runCaseFile, py::arg("path"), py::arg("out"), py::arg("quality"), py::arg("threads"),
        py::arg("seed"), py::arg("strict"), py::arg("progress"));
  m.def("check_scene", &checkScene, py::arg("files"));
  m.def("illuminance", &illuminance, py::arg("files"), py::arg("points"), py::arg("sky"), py::arg("luminaires"),
        py::arg("quality"), py::arg("seed"), py::arg("threads"), py::arg("method"), py::arg("strict"),
        py::arg("progress"));
  m.def("read_luminaire", &readLuminaire, py::arg("path"));
  m.def("sun_position", &sunPosition, py::arg("latitude"), py::arg("longitude"), py::arg("timezone"),
        py::arg("elevation"), py::arg("time"));
  m.def("file_stem", &safeFileName, py::arg("grid_name"));
  m.attr("version") = CANDELA_VERSION;
}
