// EN 12464-2:2014 outdoor work places as a study (docs/outdoor.md): each outdoor task area's
// maintained illuminance Ē and uniformity U0 from its grid (the run's grid study, with the case's
// lighting and reflections), its Ra from the luminaires' files, and the glare rating GR of CIE 112
// (metrics/glare_rating.h) at its observers: each luminaire of the scene a point source at its
// photometric centre, its intensity towards the eye times what of it passes the scene
// (obstructions), against L_ve from the area's E_hav and ρ. Verdicts from metrics/en12464_2.h.
#pragma once

#include "engine/tracer.h"
#include "metrics/en12464_2.h"
#include "reports/report_data.h"
#include "study/case/case_file.h"

#include <utility>
#include <vector>

namespace candela {

// The case's en12464-2 entry, or null.
const ComplianceSpec* en12464_2Entry(const CaseFile& c);

// An observer's lines of sight: {azimuth (degrees clockwise from plan +Y), unit sight}, its one
// `direction` or every `stepDeg` from 0, each inclined by `inclinationDeg`.
std::vector<std::pair<double, Vec3>> grLinesOfSight(const GrObserverSpec& o);

// GR along one line of sight from `eyeM`: every luminaire of the tracer's scene in front of the
// eye, E_eye = τ I cos θ / d² (τ: the photopic transmittance of the scene between eye and
// luminaire), against L_ve = `environmentVeilCdM2`.
GrViewResult glareRatingView(const Tracer& tracer, const Vec3& eyeM, const Vec3& sight, double azimuthDeg,
                             double environmentVeilCdM2);

// ρ of a task area's surface, from the scene: the mean photopic reflectance at normal incidence
// (as the report's Surfaces table gives it) of the first surface below each point of `grid`, seen
// from 0.5 m above the point. Unset when no surface lies below any point.
std::optional<double> sceneGroundReflectance(const Tracer& tracer, const GridSpec& grid);

// The areas' and observers' results: the areas' grids read from data.grids (by name), their Ra
// from data.installation's luminaire types, GR traced in `tracer` (the run's scene).
En12464_2Result computeEn12464_2(const CaseFile& c, const Tracer& tracer, const ReportData& data);

// The run's step (study/grid_study.cpp), after the grids: the entry's results as a compliance
// report with its section. Nothing without an en12464-2 entry.
void addEn12464_2Compliance(const CaseFile& c, const Tracer& tracer, ReportData& data);

}  // namespace candela
