// A climate-based annual daylight study (docs/annual.md): a case with [sky] type = "annual".
// Daylight coefficients of every grid's sensors, a year of hourly illuminance from the weather
// file, the annual metrics (DA, cDA, UDI, sDA, ASE, hours of sun) with LM-83's blinds rule,
// and the result folder: <grid>_annual.csv, the hourly float32 files, summary.csv,
// summary.json and report.html.
#pragma once

#include "study/case/case_file.h"
#include "study/observer.h"
#include "study/run_case.h"

#include <cstddef>

namespace candela {

// Sensors traced, multiplied out and written at a time (docs/annual-outputs.md, "Streaming"),
// so that the study's memory grows with the block, not with the grid. A sensor of a block holds
// its coefficients (patches + sun hours + interreflected suns: 146 + ~4400 + ~190 floats with
// Tregenza's patches, 19 KiB) and its year twice (all light and direct sun, 2 × 8760 floats,
// 68 KiB); in the blinds' second pass its closed year and its open year read back, 103 KiB. So
// about 100 MiB for a block of 1024 (study/resource_estimate.h annualBlockBytes), small beside
// 2 GB a rank, while two threads still share a thousand sensors per parallel loop. A multiple
// of kAnnualProductBlock, so a block's floats are those of the study traced whole.
inline constexpr std::size_t kAnnualSensorsPerBlock = 1024;

struct AnnualStudyOptions {
  // Rounded up to a multiple of kAnnualProductBlock (engine/daylight_coefficients.h). The
  // results do not depend on it (tests); memory and the last block's idle threads do.
  std::size_t sensorsPerBlock = kAnnualSensorsPerBlock;
};

// Throws InputError for bad input before anything is written. The hourly files are streamed into
// the run's temporary folder while the study runs (study/run_outputs.h RunOutputFolder): a run
// that fails leaves run.outDir as it was.
RunResult runAnnualStudy(const CaseFile& c, const RunContext& run, StudyObserver& observer,
                         const AnnualStudyOptions& options = {});

}  // namespace candela
