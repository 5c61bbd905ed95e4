#include "study/view_study.h"

#include "engine/camera.h"
#include "base/atomic_file.h"
#include "reports/png_writer.h"
#include "study/case/case_scene.h"
#include "study/finite_results.h"
#include "study/warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace candela {

namespace {

std::string fixed(double v, int decimals) { return formatFixed(v, decimals); }

}  // namespace

std::string relativeErrorText(double relativeStandardError) {
  if (!std::isfinite(relativeStandardError)) return "(standard error unknown)";
  return "± " + fixed(100.0 * relativeStandardError, 2) + " % (standard error)";
}

namespace {

// The report's copy of a view's pictures: the image itself up to kReportPicturePixels across,
// else averaged over k × k pixels (k the smallest that fits; the pixels inside only), so that
// an 8k rendering does not put 50 MB of PNG into the HTML page. The files keep every pixel.
constexpr int kReportPicturePixels = 2048;

struct ReportPicture {
  int width = 0, height = 0;
  const Image* image = nullptr;  // the image itself, else the averaged copies below
  std::vector<float> ownLuminance;
  std::vector<glm::vec3> ownRadiance;
  std::vector<uint8_t> ownInside;
  const std::vector<float>& luminance() const { return image ? image->luminance : ownLuminance; }
  const std::vector<glm::vec3>& radiance() const { return image ? image->radiance : ownRadiance; }
  const std::vector<uint8_t>& inside() const { return image ? image->inside : ownInside; }
};

ReportPicture reportPicture(const Image& img) {
  const int k = (std::max(img.width, img.height) + kReportPicturePixels - 1) / kReportPicturePixels;
  ReportPicture p;
  if (k <= 1) {
    p.width = img.width;
    p.height = img.height;
    p.image = &img;
    return p;
  }
  p.width = (img.width + k - 1) / k;
  p.height = (img.height + k - 1) / k;
  const std::size_t n = static_cast<std::size_t>(p.width) * p.height;
  p.ownLuminance.assign(n, 0.0f);
  p.ownRadiance.assign(n, glm::vec3(0.0f));
  p.ownInside.assign(n, 0);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      double lum = 0.0;
      Rgb rad(0.0);
      int count = 0;
      for (int yy = y * k; yy < std::min(img.height, (y + 1) * k); ++yy)
        for (int xx = x * k; xx < std::min(img.width, (x + 1) * k); ++xx) {
          const std::size_t i = img.index(xx, yy);
          if (!img.inside[i]) continue;
          lum += img.luminance[i];
          rad += Rgb(img.radiance[i]);
          ++count;
        }
      if (count == 0) continue;
      const std::size_t j = static_cast<std::size_t>(y) * p.width + x;
      p.ownLuminance[j] = static_cast<float>(lum / count);
      p.ownRadiance[j] = glm::vec3(rad / static_cast<double>(count));
      p.ownInside[j] = 1;
    }
  return p;
}

}  // namespace

ViewResult computeView(const Scene& scene, const Tracer& tracer, const ViewSpec& view, const TraceSettings& settings,
                       int threads, const ViewOptions& options, StudyObserver& observer) {
  ViewResult v;
  v.view = view;
  v.render.samplesPerPixel = options.pixelSamples;
  v.render.coarseStep = options.coarseStep;
  v.render.irradianceSamples = options.irradianceSamples;
  v.render.glossySamples = options.glossySamples;
  {
    const ObservedStep step(observer, "rendering " + view.name,
                            static_cast<std::size_t>(view.resolution.x) * view.resolution.y);
    v.image = renderView(tracer, view, settings, threads, v.render, [&step](std::size_t done, std::size_t) { step(done); },
                         options.distribution ? *options.distribution : localDistribution());
  }
  v.glare = computeViewGlare(tracer, view, settings, v.image, options.glareThresholdCdM2);
  const bool overridden = options.task && options.background;
  const std::optional<Vec3> task = overridden ? options.task : view.taskM;
  const std::optional<Vec3> background = overridden ? options.background : view.backgroundM;
  if (task && background)
    v.contrast = computeViewContrast(scene, tracer, view.positionM, *task, *background, settings,
                                     overridden ? options.contrastLoc : view.loc);
  v.scale = luminanceScale(v.image.luminance, options.logScale, options.minCdM2, options.maxCdM2);
  v.stem = safeFileName(view.name);
  return v;
}

ViewReport viewReport(const ViewResult& v) {
  const ViewSpec& view = v.view;
  const Image& img = v.image;
  ViewReport vr;
  vr.name = view.name;
  char buf[200];
  std::snprintf(buf, sizeof buf, "%s, %d × %d px, from (%.2f, %.2f, %.2f) m; files %s.exr, %s.png",
                view.type == ViewType::kFisheye ? "fisheye 180°" : "perspective", img.width, img.height,
                view.positionM.x, view.positionM.y, view.positionM.z, v.stem.c_str(), v.stem.c_str());
  vr.description = buf;
  {
    const ReportPicture pic = reportPicture(img);
    vr.falseColorPng = encodePng(luminanceFalseColor(pic.width, pic.height, pic.luminance(), v.scale));
    vr.previewPng = encodePng(toneMap(pic.width, pic.height, pic.luminance(), pic.radiance(), pic.inside()));
  }
  const ViewGlare& glare = v.glare;
  const ViewLuminance lum = viewLuminance(v);
  vr.meanLuminanceCdM2 = lum.meanCdM2;
  vr.meanLuminanceRelativeStandardError = lum.meanRelativeStandardError;
  vr.glareSourceLuminanceCdM2 = glare.sourceLuminanceCdM2;
  vr.glareSourceLuminanceRelativeStandardError = glare.sourceLuminanceRelativeStandardError;
  vr.metrics.emplace_back("Mean luminance", fixed(lum.meanCdM2, 1) + " cd/m² " +
                                                relativeErrorText(lum.meanRelativeStandardError));
  if (glare.sourceLuminanceCdM2)
    vr.metrics.emplace_back("Glare sources' luminance (DGP's, pooled)",
                            fixed(*glare.sourceLuminanceCdM2, 0) + " cd/m² " +
                                relativeErrorText(*glare.sourceLuminanceRelativeStandardError));
  vr.metrics.emplace_back("Vertical illuminance at the eye", fixed(glare.verticalLux, 1) + " lx");
  vr.metrics.emplace_back("UGR (CIE 117)", glare.sources.empty() ? "no luminaire in view"
                                                                 : fixed(glare.ugr, 1) + " (" +
                                                                       std::to_string(glare.sources.size()) +
                                                                       " luminaires)");
  if (glare.dgp) vr.metrics.emplace_back("DGP (Wienold & Christoffersen 2006)", fixed(glare.dgp->dgp, 3));
  if (v.contrast) {
    const ViewContrast& vc = *v.contrast;
    vr.metrics.emplace_back("Task / background luminance",
                            fixed(vc.taskCdM2, 2) + " / " + fixed(vc.backgroundCdM2, 2) + " cd/m²");
    vr.metrics.emplace_back("Contrast C = (Lt − Lb)/Lb", fixed(vc.contrast, 3));
    vr.metrics.emplace_back("Contrast rendition factor CRF", fixed(vc.crf(), 3));
  }
  return vr;
}

ViewImageFiles writeViewFiles(const std::filesystem::path& dir, const ViewResult& v, const std::string& comment) {
  const Image& img = v.image;
  return writeViewImageFiles(dir, v.stem, img.width, img.height, img.luminance, img.radiance, kLumensPerWatt,
                             img.inside, v.scale, comment);
}

namespace {

// The three pictures of `render` as one set: all three written (as temporaries, base/atomic_file.h)
// before any is put in place, so a failure while writing (a full disk, an encoder error) leaves
// the previous pictures as they were and no mix of old and new; only the renames, which write
// nothing, follow the first replaced file.
ViewImagePaths writeViewSet(const std::filesystem::path& dir, const ViewResult& v, const std::string& comment) {
  ViewImageFiles files = writeViewFiles(dir, v, comment);
  // A folder (or anything not a file) where a picture goes would fail its rename after the
  // others had been replaced: refused before any is.
  const ViewImagePaths targets = viewImagePaths(dir, v.stem);
  for (const std::filesystem::path& target : {targets.exr, targets.falseColor, targets.preview}) {
    const auto st = std::filesystem::symlink_status(target);
    if (std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) && !std::filesystem::is_symlink(st))
      throw std::runtime_error("'" + target.string() + "' exists and is not a file; the pictures were not replaced");
  }
  return files.commitInto(dir);
}

}  // namespace

ViewLuminance viewLuminance(const ViewResult& v) {
  const Camera cam(v.view);
  const Image& img = v.image;
  auto solidAngle = [&](std::size_t i) {
    return cam.pixelSolidAngleSr(static_cast<int>(i % img.width), static_cast<int>(i / img.width));
  };
  double sum = 0.0, omega = 0.0;
  ViewLuminance out;
  for (std::size_t i = 0; i < img.luminance.size(); ++i) {
    const double w = solidAngle(i);
    sum += img.luminance[i] * w;
    omega += w;
    out.maxCdM2 = std::max<double>(out.maxCdM2, img.luminance[i]);
  }
  out.meanCdM2 = omega > 0.0 ? sum / omega : 0.0;
  out.meanRelativeStandardError = meanStandardError(img, solidAngle) / out.meanCdM2;
  return out;
}

RenderResult renderCaseView(const std::filesystem::path& caseFile, const RenderRequest& request,
                            StudyObserver& observer) {
  CaseFile c = readCaseFile(caseFile);
  c.settings.scene = sceneReadOptions(&c.settings, request.trace);
  c.settings.scene.maxMemoryBytes = request.limits.maxMemoryBytes;
  const FileLoc atCase{c.path.string(), 0, 0};
  const ViewSpec* view = nullptr;
  for (const ViewSpec& v : c.views)
    if (v.name == request.view) view = &v;
  if (!view) {
    std::string names;
    for (const ViewSpec& v : c.views) names += (names.empty() ? "" : ", ") + v.name;
    throw InputError(atCase, "no [[view]] named '" + request.view + "' (" +
                                 (names.empty() ? "the case has no views" : "views: " + names) + ")");
  }
  const ViewOptions& o = request.options;
  if (o.logScale && o.minCdM2 && *o.minCdM2 == 0.0)
    throw InputError(atCase, "--min must be above 0 cd/m2 on a log scale");
  if (o.minCdM2 && o.maxCdM2 && *o.maxCdM2 <= *o.minCdM2) throw InputError(atCase, "--max must be above --min");
  const std::unique_ptr<Scene> scene = loadCaseScene(c);
  // The settings `candela run` gives the case's views.
  const ResolvedTrace trace = resolveTrace(&c.settings, request.trace, Method::kCache);
  const std::filesystem::path outDir = request.outDir.empty() ? c.output.dir : request.outDir;
  const ResourceEstimate needs =
      estimateView(c, *view, ViewWork{o.pixelSamples, o.coarseStep, o.irradianceSamples}, *scene, trace.settings,
                   trace.threads);
  checkResources(needs, request.limits, atCase);
  observer.estimated(needs);
  const Tracer tracer(*scene);
  RenderResult r;
  checkSceneInput(*scene, r.warnings);
  checkLightSources(*scene, atCase, r.warnings);
  checkCaseSite(c, r.warnings);
  checkSkySun(c, *scene, r.warnings);
  checkLuminaires(tracer, c.luminaires, {}, r.warnings);
  checkPhotometry(*scene, c.luminaires, r.warnings);
  throwIfStrict(r.warnings, request.strict);
  r.caseName = c.name;
  r.view = computeView(*scene, tracer, *view, trace.settings, trace.threads, o, observer);
  checkFinite(r.view.image.luminance, "view '" + view->name + "'");
  if (o.distribution && !o.distribution->writesOutputs()) return r;  // rank 0 writes the images
  try {
    r.paths = writeViewSet(outDir, r.view,
                           "candela " + std::string(CANDELA_VERSION) + ", case " + c.name + ", view " + view->name);
  } catch (const std::filesystem::filesystem_error& e) {
    throw InputError(FileLoc{outDir.string(), 0, 0}, std::string("cannot write the images: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw InputError(FileLoc{outDir.string(), 0, 0}, std::string("cannot write the images: ") + e.what());
  }
  return r;
}

}  // namespace candela
