#include "engine/materials/pattern_hook.h"

#include "engine/radiance/text_pattern.h"

#include <algorithm>

namespace candela {

void PatternEvaluator::begin(const ScenePattern& sp, const PatternPoint& p) {
  cal::Environment env;
  fill(sp, p, env);
  eval_->begin(env);
}

void PatternEvaluator::fill(const ScenePattern& sp, const PatternPoint& p, cal::Environment& env) {
  if (!eval_) eval_ = std::make_unique<cal::Evaluator>(*scene_.functions);
  // The ray's variables in the function's coordinates (Radiance's func.c: the point, direction
  // and normal through the inverse of the pattern's transform; T in its units).
  const RadTransform& f = sp.toFunction;
  const Vec3 x = f.point(p.x), d = glm::normalize(f.direction(p.d)), n = glm::normalize(f.direction(p.ng));
  const Vec3 o = f.point(Vec3(0.0)), ix = f.direction(Vec3(1, 0, 0)), jy = f.direction(Vec3(0, 1, 0)),
             kz = f.direction(Vec3(0, 0, 1));
  const double values[] = {d.x, d.y, d.z, n.x, n.y, n.z, x.x, x.y, x.z};
  for (int k = 0; k < 9; ++k) env.ray[k] = values[k];
  env.ray[cal::kT] = env.ray[cal::kTs] = p.t / sp.functionScale;
  env.ray[cal::kRdot] = env.ray[cal::kRdotP] = -glm::dot(p.d, p.ng);
  env.ray[cal::kS] = sp.functionScale;
  env.ray[cal::kTx] = o.x, env.ray[cal::kTy] = o.y, env.ray[cal::kTz] = o.z;
  env.ray[cal::kIx] = ix.x, env.ray[cal::kIy] = ix.y, env.ray[cal::kIz] = ix.z;
  env.ray[cal::kJx] = jy.x, env.ray[cal::kJy] = jy.y, env.ray[cal::kJz] = jy.z;
  env.ray[cal::kKx] = kz.x, env.ray[cal::kKy] = kz.y, env.ray[cal::kKz] = kz.z;
  env.ray[cal::kNxP] = n.x, env.ray[cal::kNyP] = n.y, env.ray[cal::kNzP] = n.z;
  env.args = sp.args;
}

double PatternEvaluator::function(const ScenePattern& sp, int k) {
  try {
    if (sp.coordinates.empty()) return eval_->value(sp.functions[static_cast<size_t>(k)]);
    // A data pattern: the lookup point (a picture's: v then u, Radiance's y-major order), the
    // values there, and the function of channel k called with them.
    double pt[kMaxDataDimensions];
    const size_t n = sp.coordinates.size();
    for (size_t i = 0; i < n; ++i) pt[sp.picture ? n - 1 - i : i] = eval_->value(sp.coordinates[i]);
    double values[3];
    size_t count = 0;
    for (const auto& d : sp.data)
      if (d) values[count++] = d->value(pt);
    return eval_->call(sp.functions[static_cast<size_t>(k)], std::span<const double>(values, count));
  } catch (const cal::EvalError& e) {
    throw InputError(sp.loc, sp.type + " '" + sp.name + "': " + e.what());
  }
}

Rgb PatternEvaluator::spectral(const ScenePattern& sp) {
  // Radiance's p_specfunc and p_specdata: the function of the wavelength (specdata: of the data's
  // value there too, at the point the coordinates give) at each node, reduced to RGB.
  try {
    double pt[kMaxDataDimensions];
    const size_t n = sp.coordinates.size();
    for (size_t i = 0; i < n; ++i) pt[i] = eval_->value(sp.coordinates[i]);
    Rgb c(0.0);
    for (size_t k = 0; k < sp.spectralNodesNm.size(); ++k) {
      const double nm = sp.spectralNodesNm[k];
      double args[2] = {nm, nm};
      if (sp.data[0]) {
        pt[n] = nm;
        args[0] = sp.data[0]->value(pt);
      }
      c += eval_->call(sp.functions[0], std::span<const double>(args, sp.data[0] ? 2 : 1)) * sp.spectralWeights[k];
    }
    return c;
  } catch (const cal::EvalError& e) {
    throw InputError(sp.loc, sp.type + " '" + sp.name + "': " + e.what());
  }
}

Rgb PatternEvaluator::colour(int index, const PatternPoint& p) {
  Rgb c(1.0);
  for (int i = index; i >= 0;) {
    const ScenePattern& sp = scene_.patterns[static_cast<size_t>(i)];
    if (sp.kind != PatternKind::kFunction) break;  // native patterns act elsewhere (sources, skies)
    if (sp.constant) {
      c *= sp.constantColour;
    } else if (sp.text) {  // brighttext, colortext: foreground in a glyph, background elsewhere
      c *= sp.text->colour(p.x);
    } else if (!sp.texture) {  // a texture perturbs the normal (perturbation), no colour
      begin(sp, p);
      if (sp.spectral()) {
        c *= spectral(sp);
      } else if (sp.channels == 1) {
        c *= function(sp, 0);
      } else {
        for (int k = 0; k < 3; ++k) c[k] *= function(sp, k);
      }
    }
    i = sp.next;
  }
  return c;
}

double PatternEvaluator::value(int index, const PatternPoint& p) {
  const ScenePattern& sp = scene_.patterns[static_cast<size_t>(index)];
  if (sp.text) return sp.text->inside(p.x) ? 1.0 : 0.0;  // mixtext: the foreground in a glyph
  begin(sp, p);
  return function(sp, 0);
}

void PatternEvaluator::beginOriented(const ScenePattern& sp, const PatternPoint& p, const Rgb& colourP) {
  cal::Environment env;
  fill(sp, p, env);
  // Radiance's m_brdf.c (setbrdfunc): the perturbed normal and RdotP turned towards the ray,
  // the pattern's colour as CrP CgP CbP; Rdot keeps its sign.
  const double rdot = -glm::dot(p.d, p.ng);
  const Vec3 n = glm::normalize(sp.toFunction.direction(rdot < 0.0 ? -p.ng : p.ng));
  env.ray[cal::kNxP] = n.x, env.ray[cal::kNyP] = n.y, env.ray[cal::kNzP] = n.z;
  env.ray[cal::kRdotP] = std::min(1.0, std::abs(rdot));
  env.ray[cal::kCrP] = colourP.x, env.ray[cal::kCgP] = colourP.y, env.ray[cal::kCbP] = colourP.z;
  eval_->begin(env);
}

Rgb PatternEvaluator::oriented(int index, const PatternPoint& p, const Rgb& patternColour) {
  const ScenePattern& sp = scene_.patterns[static_cast<size_t>(index)];
  beginOriented(sp, p, patternColour);
  Rgb c(0.0);
  for (int k = 0; k < 3; ++k) c[k] = function(sp, k);
  return c;
}

Rgb PatternEvaluator::directional(int index, const PatternPoint& p, const Rgb& colourP, const Vec3& ldir,
                                  double omegaSr) {
  const ScenePattern& sp = scene_.patterns[static_cast<size_t>(index)];
  beginOriented(sp, p, colourP);
  // Radiance's dirbrdf: the light's direction through the function's transform, its scale taken
  // out; then the source's solid angle. A data form's function gets the value looked up first.
  const Vec3 l = glm::normalize(sp.toFunction.direction(ldir));
  double args[5] = {0.0, l.x, l.y, l.z, omegaSr};
  const std::span<const double> light(args + 1, 4);
  try {
    if (!sp.coordinates.empty()) {
      double pt[kMaxDataDimensions];
      for (size_t i = 0; i < sp.coordinates.size(); ++i) pt[i] = eval_->call(sp.coordinates[i], light);
      args[0] = sp.data[0]->value(pt);
      return Rgb(eval_->call(sp.functions[0], std::span<const double>(args, 5)));
    }
    Rgb c(0.0);
    for (int k = 0; k < sp.channels; ++k)
      if (sp.functions[static_cast<size_t>(k)] >= 0) c[k] = eval_->call(sp.functions[static_cast<size_t>(k)], light);
    return sp.channels == 1 ? Rgb(c.x) : c;
  } catch (const cal::EvalError& e) {
    throw InputError(sp.loc, sp.type + " '" + sp.name + "': " + e.what());
  }
}

Vec3 PatternEvaluator::perturbation(int index, const PatternPoint& p) {
  Vec3 sum(0.0);
  for (int i = index; i >= 0;) {
    const ScenePattern& sp = scene_.patterns[static_cast<size_t>(i)];
    if (sp.kind != PatternKind::kFunction) break;
    if (sp.texture) {
      begin(sp, p);
      Vec3 v(0.0);
      for (int k = 0; k < 3; ++k) v[k] = function(sp, k);
      // Radiance's t_func.c: the displacement turned to the world, its scale taken out.
      sum += sp.toWorld.direction(v) / sp.functionScale;
    }
    i = sp.next;
  }
  return sum;
}

Vec3 PatternEvaluator::direction(int index, const PatternPoint& p) {
  const ScenePattern& sp = scene_.patterns[static_cast<size_t>(index)];
  begin(sp, p);
  Vec3 v(0.0);
  for (int k = 0; k < 3; ++k) v[k] = function(sp, k);
  return sp.toWorld.direction(v);
}

const Material& patterned(const Scene& scene, const Material& m, const PatternPoint& p, PatternEvaluator& eval,
                          Material& out) {
  if (!hasFunctionPattern(scene, m)) return m;
  static_cast<MaterialParameters&>(out) = m;
  Rgb pc(1.0);
  if (m.pattern >= 0 && scene.patterns[static_cast<size_t>(m.pattern)].kind == PatternKind::kFunction) {
    // A negative brightness is no light: 0 (Radiance would carry it on as negative light).
    pc = glm::max(eval.colour(m.pattern, p), Rgb(0.0));
    out.color = m.color * pc;
    deriveMaterial(out);
    out.perturbation = eval.perturbation(m.pattern, p);
  }
  out.patternColour = pc;
  if (m.functions >= 0) familyOf(m).atHit(m, p, pc, eval, out);
  return out;
}


namespace {
constexpr int kMaxNesting = 16;  // mixtures of mixtures, illums' alternates

const Material* component(const Scene& scene, int index) {
  return index < 0 ? nullptr : &scene.materials[static_cast<size_t>(index)];
}
}  // namespace

const Material* resolved(const Scene& scene, const Material& m, const PatternPoint& p, PatternEvaluator& eval,
                         Rng& rng) {
  const Material* at = &m;
  for (int k = 0; k < kMaxNesting && at; ++k) {
    const MaterialFamily& family = familyOf(*at);
    if (const std::optional<int> other = family.seenInstead(*at)) {
      at = component(scene, *other);
    } else if (family.role() == HitRole::kMix) {
      const double c = std::clamp(eval.value(at->pattern, p), 0.0, 1.0);
      at = component(scene, rng.uniform() < c ? at->foreground : at->background);
    } else {
      return at;
    }
  }
  return at;
}

namespace {
std::optional<Rgb> throughAt(const Scene& scene, const Material* m, const PatternPoint& p, PatternEvaluator& eval,
                             int depth) {
  if (!m) return Rgb(1.0);  // void: nothing there
  const MaterialFamily& family = familyOf(*m);
  if (family.role() == HitRole::kMix && depth < kMaxNesting) {
    const double c = std::clamp(eval.value(m->pattern, p), 0.0, 1.0);
    const std::optional<Rgb> f = throughAt(scene, component(scene, m->foreground), p, eval, depth + 1);
    const std::optional<Rgb> b = throughAt(scene, component(scene, m->background), p, eval, depth + 1);
    if (!f && !b) return std::nullopt;
    return c * f.value_or(Rgb(0.0)) + (1.0 - c) * b.value_or(Rgb(0.0));
  }
  if (!hasFunctionPattern(scene, *m)) return family.straightTransmittance(*m, p.d, p.ng);
  Material copy;
  const Material& pm = patterned(scene, *m, p, eval, copy);
  return family.straightTransmittance(pm, p.d, p.ng);
}
}  // namespace

std::optional<Rgb> straightThrough(const Scene& scene, const Material& m, const PatternPoint& p,
                                   PatternEvaluator& eval) {
  return throughAt(scene, &m, p, eval, 0);
}

}  // namespace candela

namespace candela {

const Material* materialAt(const Scene& scene, const Material& m, const PatternPoint& p,
                           std::unique_ptr<PatternEvaluator>& evaluator, Rng& rng,
                           std::optional<Material>& patternedCopy) {
  if (!scene.functions) return seenMaterial(scene.materials, m);
  if (!evaluator) evaluator = std::make_unique<PatternEvaluator>(scene);
  PatternEvaluator& eval = *evaluator;
  const Material* at = resolved(scene, m, p, eval, rng);
  if (at && hasFunctionPattern(scene, *at)) at = &patterned(scene, *at, p, eval, patternedCopy.emplace());
  return at;
}

}  // namespace candela
