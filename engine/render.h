// Luminance images of [[view]]s: camera rays through the tracer, with adaptive image-plane
// sampling (a coarse lattice first, then refinement only where the luminance varies), and the
// luminaires the eye sees for glare ratings. docs/views.md explains the method and its limits.
#pragma once

#include "base/distribution.h"
#include "engine/camera.h"
#include "engine/tracer.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace candela {

// A rendered view. Pixels are row-major, top row first. Values are held as 32-bit floats (the
// precision of the EXR written from them): 23 bytes a pixel, 1.44 GiB for 8192 × 8192.
struct Image {
  int width = 0, height = 0;
  std::vector<glm::vec3> radiance;  // Radiance RGB radiance, W/sr/m²
  std::vector<float> luminance;      // photopic luminance, cd/m² (179 · photopic(radiance))
  std::vector<float> standardError;  // of each luminance, cd/m² (traced pixels: from their samples)
  std::vector<uint8_t> inside;       // 1 where the pixel centre has a ray (0 outside a fisheye's circle)
  std::vector<uint8_t> traced;       // 1 where the pixel was traced, 0 where interpolated
  // How each interpolated pixel inside the image was made: bilinearly from the four corners of
  // its block on the lattice of spacing 2^level (interpolationCorners), this level; 0 for traced
  // pixels and pixels outside. What meanStandardError needs to carry their errors back to the
  // traced pixels they came from.
  std::vector<uint8_t> interpolationLevel;
  std::size_t tracedPixels = 0;
  std::size_t cameraRays = 0;
  int samplesPerPixel = 0;         // camera rays per traced pixel (its standard error needs 2 or more)

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

// The block of the refinement lattice of spacing `spacing` (lines at its multiples and at the
// last pixel, size − 1) that pixel coordinate c is interpolated in: its lines c0 ≤ c ≤ c1, and
// the weight of c1, f = (c − c0) / (c1 − c0) (0 when c0 = c1).
struct LatticeInterval {
  int c0 = 0, c1 = 0;
  double f = 0.0;
};
LatticeInterval interpolationInterval(int size, int spacing, int c);

struct RenderSettings {
  int samplesPerPixel = 4;        // camera rays per traced pixel, stratified over the pixel
  // Pixels between the samples of the first, coarse pass (rounded down to a power of two; 1 traces
  // every pixel). Features smaller than this may be missed where the lattice misses them.
  int coarseStep = 4;
  // A block of the lattice is refined when its corners' luminances differ by more than this
  // fraction of their mean plus `noiseAllowance` standard errors of the corner values (so that
  // converged Monte Carlo noise alone does not force refinement), or when a corner's standard
  // error exceeds this fraction of the mean (too noisy to tell: refined, never interpolated).
  double refineThreshold = 0.05;
  double noiseAllowance = 2.0;
  // With irradianceSamples > 0, a camera ray meeting a matte opaque surface (plastic or metal
  // without specular lobe) takes L = ρ E / π from the sensor estimator's irradiance there, with
  // this many hemisphere samples and `irradianceLightSamples` per source, instead of following
  // one path: direct light exact where a source is wholly visible, indirect stratified. Costs
  // about irradianceSamples paths per camera ray; other surfaces are path traced.
  // The same estimator then follows what the camera sees through specular events: a mirror,
  // thin glass (transmitted and reflected both followed while each carries 2 % of the ray, the
  // rest by roulette), a dielectric boundary, trans's straight-on part; matte surfaces seen in
  // a window or through it take ρ E / π as well, so a window is not salt-and-pepper. A glossy
  // (Ward) lobe of a surface seen takes `glossySamples` paths per camera ray.
  int irradianceSamples = 0;
  int irradianceLightSamples = 4;
  int glossySamples = 8;
  // Photometric luminaires have no geometry: draw their luminous openings (L = I / projected
  // area) so that they appear in images and glare evaluations.
  bool showLuminaires = true;
  // Pixels traced or interpolated per fill (base/distribution.h): a pass goes out in bands of
  // whole lattice rows of about this many pixels, so that the pass's lists and values stay
  // bounded whatever the image's size. The image does not depend on it.
  std::size_t pixelsPerFill = std::size_t{1} << 20;
};

// Called with the number of pixels settled (traced or interpolated) so far, of `total`;
// from several threads at once.
using RenderProgress = std::function<void(std::size_t done, std::size_t total)>;

// Renders a view with `settings.maxBounces` interreflections after the direct light on the
// surfaces seen (the same light a sensor grid gets with those settings). Every pixel's luminance depends only on (seed, pixel) and the refinement
// decisions, which depend only on traced values, so the image is identical for any `threads`
// (0 = all cores), and for any split of the pixels between the processes of `distribution`
// (every process gets the whole image; progress counts this process's pixels).
// 7 parameters: the view and its settings, threads, progress and processes.
Image renderView(const Tracer& tracer, const View& view, const TraceSettings& settings, int threads,
                 const RenderSettings& render = {}, const RenderProgress& progress = {},
                 const Distribution& distribution = localDistribution());

// Standard error (cd/m²) of the weighted mean Σ wᵢ Lᵢ / Σ wᵢ of the image's luminances
// (`weight(i)` for pixel i, e.g. its solid angle; 0 leaves a pixel out), from the traced pixels'
// standard errors (independent: each pixel its own random stream) with every interpolated pixel's
// weight carried back to the traced pixels it came from. Monte Carlo noise only: the error of
// interpolating between lattice points is not in it. NaN when the traced pixels have fewer than
// two camera rays each (no spread to estimate from) or the weights sum to 0.
using PixelWeight = std::function<double(std::size_t pixel)>;
double meanStandardError(const Image& img, const PixelWeight& weight);

// Direction (view frame: x right, y up, z forward) and solid angle (sr) of each pixel centre of
// a view, for glare evaluations from the image, computed when asked (an 8k image's geometry
// would take 2 GiB); pixels without a ray get a zero direction and solid angle 0.
class ViewGeometry {
 public:
  explicit ViewGeometry(const View& view);
  void operator()(std::size_t pixel, Vec3& directionView, double& solidAngleSr) const;

 private:
  Camera cam_;
};

// A photometric luminaire as the eye at `eye` sees it: the luminous opening's mean luminance
// towards the eye, I(dir to eye) / projected area, and its solid angle (projected area / d²).
struct SeenLuminaire {
  std::string name;
  Vec3 directionWorld{0.0};     // unit, from the eye to the luminaire's photometric centre
  Vec3 directionView{0.0};      // the same in the view frame (x right, y up, z forward), when known
  double distanceM = 0.0;
  double luminanceCdM2 = 0.0;
  double solidAngleSr = 0.0;
  // Its direct illuminance on a plane facing `viewDir` at the eye, in lux: the opening integrated
  // as an area source (8 × 8 cells with a shadow ray each), occlusion included.
  double illuminanceLux = 0.0;
  double transmittance = 1.0;   // visible fraction of that illuminance (0: hidden, 1: in full view)
};

// Luminaires with a luminous opening (point luminaires have no area and are left out) in front of
// the eye (towards `viewDir`), with their transmittance through the scene (0: hidden).
std::vector<SeenLuminaire> seenLuminaires(const Tracer& tracer, const Vec3& eye, const Vec3& viewDir);

// The light at a view's eye point for glare ratings: the vertical illuminance (facing the view
// direction, the tracer's estimate with `settings`, random stream `stream`), the luminaires seen
// (with view-frame directions for position indices) and their direct share of that illuminance.
struct EyeLight {
  double verticalLux = 0.0;
  double directLuminaireLux = 0.0;
  std::vector<SeenLuminaire> luminaires;
  // UGR's background luminance (CIE 117): the indirect illuminance at the eye over π, the
  // indirect part being everything but the luminaires' direct light.
  double backgroundLuminanceCdM2() const;
};
EyeLight eyeLight(const Tracer& tracer, const View& view, const TraceSettings& settings, uint64_t stream = 0);

// Luminance in cd/m² of the surface point `target` seen from `eye` (contrast of a task against
// its background, metrics/contrast.h): a matte opaque surface gives ρ E / π with E the sensor
// estimator's irradiance there (`settings`, random stream `stream`); any other surface the mean
// of `pathSamples` camera paths through the point. 0 when nothing is hit.
double luminanceToward(const Tracer& tracer, const Vec3& eye, const Vec3& target, const TraceSettings& settings,
                       uint64_t stream, int pathSamples = 256);

// The shape the eye at `eye` sees in the direction of `target` (kNoShape when none).
uint32_t shapeToward(const Tracer& tracer, const Vec3& eye, const Vec3& target);

// CRF's reference: the task in a photometric sphere. Only the shapes `keepShapes` (the task's and
// its background's surfaces, e.g. from shapeToward) with their materials (emitters black), no
// luminaires, sky or distant sources, and a uniform sphere of luminance `luminanceCdM2` (a 360°
// glow) all around. Keep it alive while a Tracer uses it.
Scene referenceSphereScene(const Scene& scene, const std::vector<uint32_t>& keepShapes, double luminanceCdM2 = 100.0);

}  // namespace candela
