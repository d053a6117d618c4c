// ocean_spectrum: the spectral ocean's settings (docs/ocean.md) as a node. It
// computes nothing in the water's shaders: its `ocean` output is a handle the
// ocean_* readers take, and the planner turns each distinct spectrum the
// outputs reach into simulation passes (initial amplitudes, evolution, inverse
// FFT, packing) that fill the maps they read.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/emit_context.h"
#include "core/ocean_settings.h"
#include "nodes/node_library.h"
#include "nodes/ocean_reference.h"
#include "nodes/port_builders.h"

namespace wg::nodes {
namespace {

constexpr double kDegree = ocean::kPi / 180.0;
// The options' defaults that cascade_sizes' levels also read.
constexpr int kDefaultFftSize = 256;
nlohmann::json defaultTileLengths() { return nlohmann::json::array({400, 60, 9}); }

std::string validateTileLengths(const nlohmann::json& v) {
  if (!v.is_array() || v.empty() || v.size() > static_cast<size_t>(ocean::kMaxCascades))
    return "must list 1 to " + std::to_string(ocean::kMaxCascades) + " tile lengths in metres, the longest first";
  for (const auto& l : v)
    if (!l.is_number() || !std::isfinite(l.get<double>())) return "must list finite numbers of metres";
  return "";
}

// cascade_sizes' own check: whole numbers (a size's power of two, range and count are
// the settings' checks, ocean::validateCascades, which name the cascade).
std::string validateCascadeSizes(const nlohmann::json& v) {
  if (!v.is_array() || v.size() > static_cast<size_t>(ocean::kMaxCascades))
    return "must list one size a cascade (texels along its side), or none for fft_size everywhere";
  for (const auto& n : v)
    if (!n.is_number() || !std::isfinite(n.get<double>()) || n.get<double>() != std::floor(n.get<double>()) ||
        std::abs(n.get<double>()) > 1e6)
      return "must list whole numbers of texels, each a power of two in [" +
             std::to_string(ocean::kMinCascadeResolution) + ", " + std::to_string(ocean::kMaxResolution) + "]";
  return "";
}

// The tune levels of cascade_sizes for a node as written: every cascade but the finest at a
// quarter, then at half of fft_size (at least 16), the finest at fft_size; most exact, none
// (every cascade at fft_size). The long tiles' bands end near their 12th bin (docs/ocean.md,
// "Cascades"), so a quarter of 256 still holds their waves: only the maps' bilinear
// reconstruction between fewer texels changes.
std::vector<nlohmann::json> cascadeSizeLevels(const nlohmann::json& written) {
  const nlohmann::json fft = written.value("fft_size", nlohmann::json(kDefaultFftSize));
  const nlohmann::json tiles = written.value("tile_lengths", defaultTileLengths());
  if (!fft.is_number_integer() || !tiles.is_array() || tiles.size() < 2) return {};
  const int n = fft.get<int>();
  std::vector<nlohmann::json> levels;
  for (int divisor : {4, 2}) {
    nlohmann::json sizes = nlohmann::json::array();
    for (size_t c = 0; c + 1 < tiles.size(); ++c) sizes.push_back(std::max(n / divisor, ocean::kMinCascadeResolution));
    sizes.push_back(n);
    levels.push_back(std::move(sizes));
  }
  levels.push_back(nlohmann::json::array());
  return levels;
}

// The tune levels of cascade_count for a node as written: the longest tile alone, then one
// tile more at each level, to every tile listed (the reference). A sea of one tile has none.
std::vector<nlohmann::json> cascadeCountLevels(const nlohmann::json& written) {
  const nlohmann::json tiles = written.value("tile_lengths", defaultTileLengths());
  if (!tiles.is_array() || tiles.size() < 2 || tiles.size() > static_cast<size_t>(ocean::kMaxCascades)) return {};
  std::vector<nlohmann::json> levels;
  for (size_t n = 1; n <= tiles.size(); ++n) levels.push_back(static_cast<int>(n));
  return levels;
}

OptionSpec cascadeCountOption() {
  OptionSpec o = ports::integer(
      "cascade_count", ocean::kMaxCascades, 1, ocean::kMaxCascades,
      "how many of tile_lengths' tiles are simulated, the longest first (more than listed: all). The last one "
      "simulated carries every wave its grid holds, so fewer cascades drop only the waves shorter than its grid "
      "reaches. Quality knob: the longest tile alone, then one tile more a level, to every tile listed");
  o.levelsFor = cascadeCountLevels;
  return o;
}

// cascade_count keeps the first `count` tiles (and their cascade_sizes), the longest first.
// Only lists that are meaningful as written are cut, so that an error in a tile or size the
// count drops is still reported (checkOptions validates what the parser returns).
void keepFirstCascades(ocean::CascadeSettings& c, int count) {
  if (ocean::validateCascades(c)) return;
  const size_t n = std::min(c.tileLengths.size(), static_cast<size_t>(std::max(count, 1)));
  c.tileLengths.resize(n);
  if (!c.sizes.empty()) c.sizes.resize(n);
}

// An Integer option past int's range: any 32-bit seed.
OptionSpec seedOption() {
  OptionSpec o = ports::integer("seed", 0, 0, 0, "the random sea's seed, a whole number from 0 to 2^32 - 1");
  o.max = 4294967295.0;
  return o;
}

OptionSpec cascadeSizesOption() {
  OptionSpec o = ports::checked(
      OptionSpec::Kind::Json, "cascade_sizes", nlohmann::json::array(), validateCascadeSizes,
      "each cascade's own texels along its side (powers of two in [16, 512], one a tile, the "
      "longest tile's first), at most fft_size (which caps them); empty: every cascade at "
      "fft_size. A long tile's band ends near its 12th bin, so 64 holds its waves as 256 does, "
      "for a sixteenth of the simulation's cost. Quality knob: every cascade but the finest at "
      "fft_size / 4, then / 2, then none");
  o.levelsFor = cascadeSizeLevels;
  return o;
}

ocean::OceanSettings parseOceanSettings(const OptionReader& o) {
  ocean::OceanSettings s;
  ocean::SpectrumSettings& p = s.spectrum;
  p.model = o.choice<ocean::SpectrumModel>("model", {{"phillips", ocean::SpectrumModel::Phillips},
                                                     {"pierson_moskowitz", ocean::SpectrumModel::PiersonMoskowitz},
                                                     {"jonswap", ocean::SpectrumModel::Jonswap},
                                                     {"tma", ocean::SpectrumModel::Tma}});
  p.spreading = o.choice<ocean::Spreading>("spreading", {{"cos2", ocean::Spreading::Cos2},
                                                         {"mitsuyasu", ocean::Spreading::Mitsuyasu},
                                                         {"hasselmann", ocean::Spreading::Hasselmann}});
  p.windSpeed = o.number("wind_speed");
  p.windDirection = o.number("wind_direction") * kDegree;
  p.fetch = o.number("fetch") * 1000.0;
  p.depth = o.number("depth");
  p.gamma = o.number("gamma");
  p.phillipsAmplitude = o.number("phillips_amplitude");
  p.phillipsSmallWave = o.number("phillips_small_wave");
  p.swell.height = o.number("swell_height");
  p.swell.period = o.number("swell_period");
  p.swell.direction = o.number("swell_direction") * kDegree;
  p.swell.spread = o.number("swell_spread");
  ocean::CascadeSettings& c = s.cascades;
  c.resolution = o.integer("fft_size");
  c.tileLengths.clear();
  for (const auto& l : o.json("tile_lengths")) c.tileLengths.push_back(l.get<double>());
  for (const auto& n : o.json("cascade_sizes")) c.sizes.push_back(static_cast<int>(n.get<double>()));
  c.choppiness = o.number("choppiness");
  c.seed = o.wholeNumber("seed");
  keepFirstCascades(c, o.integer("cascade_count"));
  ocean::FoamSettings& f = s.foam;
  f.threshold = o.number("foam_threshold");
  f.growth = o.number("foam_growth");
  f.decay = o.number("foam_decay");
  f.step = o.number("foam_step");
  f.cascades = o.integer("foam_cascades");
  return s;
}

}  // namespace

NodeSpec oceanSpectrumNode() {
  NodeSpec s;
  s.type = "ocean_spectrum";
  s.family = "waves";
  s.summary =
      "A random sea from a wind-wave spectrum in 1 to 4 cascades of "
      "square tiles, simulated by inverse FFT in "
      "passes planned for the graph; its readers (ocean_displacement, "
      "ocean_surface) take its `ocean` output.";
  s.formula =
      "h(x, t) = sum over k of h~(k, t) exp(i k.x), h~(k, t) = h0(k) "
      "exp(-i w t) + conj(h0(-k)) exp(i w t), "
      "w^2 = g k tanh(k d), h0(k) = (xi_r + i xi_i) sqrt(F(k) dk^2) / "
      "2 with counter-based Gaussian xi, "
      "F = S(w) D(theta) (dw/dk) / k; displacement D = sum of i k/|k| "
      "h~ exp(i k.x) times the choppiness. "
      "docs/ocean.md gives the spectra, the spreading functions, the "
      "cascades' bands and the units.";
  s.source =
      "Tessendorf, Simulating Ocean Water (2001); Hasselmann et al. "
      "1973 (JONSWAP); Bouws et al. 1985 (TMA)";
  s.cost =
      "no shader code; per frame and cascade 2 log2 N + 2 full passes "
      "over N x N RGBA32F texels (evolution, "
      "the FFT's Stockham stages, packing); the initial spectrum only "
      "when its options change";
  s.outputs = {ports::fixed("ocean", Type::Ocean, "the simulated sea, for the ocean_* readers")};
  s.options = {
      ports::choice("model", {"phillips", "pierson_moskowitz", "jonswap", "tma"}, "jonswap",
                    "the wave spectrum: Phillips (Tessendorf's), "
                    "Pierson-Moskowitz (a fully developed sea), "
                    "JONSWAP (a sea growing over `fetch`), TMA (JONSWAP in "
                    "water of finite `depth`)"),
      ports::choice("spreading", {"cos2", "mitsuyasu", "hasselmann"}, "hasselmann",
                    "the directional spreading: cos^2 (waves with and against the wind), "
                    "or the cos-2s forms of "
                    "Mitsuyasu (1975) and Hasselmann (1980), narrower near the peak"),
      ports::number("wind_speed", 10, 0, 100, "U10, the mean wind 10 m above the sea, m/s; 0 is a flat calm"),
      ports::number("wind_direction", 0, -360, 360, "degrees from +x towards +z, the way the wind blows"),
      ports::number("fetch", 100, 0, 1e5,
                    "km of open water upwind (JONSWAP, TMA); past about 1.7e4 "
                    "U10^2 / g the sea is fully developed"),
      ports::number("depth", 10000, 0, 10000,
                    "water depth, m: enters the dispersion always and the "
                    "spectrum in TMA; 10000 is deep water for "
                    "every wave a cascade holds"),
      ports::number("gamma", 3.3, 1, 20, "JONSWAP's peak enhancement"),
      ports::number("phillips_amplitude", 1e-3, 0, 1, "Phillips' A (dimensionless)"),
      ports::number("phillips_small_wave", 0, 0, 100, "Phillips' suppression length l, m: exp(-k^2 l^2)"),
      ports::number("swell_height", 0, 0, 30, "significant height of a swell from afar, m; 0: none"),
      ports::number("swell_period", 10, 1, 60, "the swell's peak period, s"),
      ports::number("swell_direction", 0, -360, 360, "degrees from +x towards +z, the way the swell travels"),
      ports::number("swell_spread", 20, 0, 1000, "the swell's cos-2s exponent (larger: narrower)"),
      ports::checked(OptionSpec::Kind::Json, "tile_lengths", defaultTileLengths(), validateTileLengths,
                     "each cascade's square tile, m, the longest first: 1 to 4 "
                     "tiles, each shorter than the previous by "
                     "less than N/2 - 1 times (so no wavenumber between the "
                     "grids is lost)"),
      ports::knob(ports::integer("fft_size", kDefaultFftSize, ocean::kMinResolution, ocean::kMaxResolution,
                                 "texels along a tile's side, a power of two; "
                                 "fewer drop the shortest waves (cascade_sizes can lower it per cascade)"),
                  {64, 128, 256}),
      cascadeSizesOption(),
      cascadeCountOption(),
      ports::number("choppiness", 1, 0, 4,
                    "lambda: the horizontal displacement's scale; positive "
                    "sharpens crests"),
      seedOption(),
      ports::number("foam_threshold", 0.6, -1, 2,
                    "the persistent foam (ocean_foam) grows where a cascade's Jacobian J is below this "
                    "(1 on still water, below 0 where the surface folds)"),
      ports::number("foam_growth", 3, 0, 1000, "foam per second per unit of J below foam_threshold"),
      ports::number("foam_decay", 1.5, 0.02, 100, "seconds for foam to fall to 1/e; at most 100 foam steps"),
      ports::knob(ports::number("foam_step", 0.1, ocean::kFoamMinStep, ocean::kFoamMaxStep,
                                "seconds between the foam's steps (a frame interpolates between two); a still "
                                "frame replays 5 decay times of them"),
                  {0.2, 0.1}),
      ports::integer("foam_cascades", 4, 1, 4,
                     "only the first (longest) this many cascades make foam: a short tile's folds are "
                     "spray too small to foam, and each foam cascade costs its own steps"),
  };
  s.parseOptions = optionParser(parseOceanSettings);
  s.checkOptions = [](const ParsedOptions& options) -> std::optional<NodeSpec::OptionProblem> {
    const auto& settings = options.as<ocean::OceanSettings>();
    if (auto e = ocean::validateOcean(settings)) {
      // The settings speak of the fetch in metres; the option is in km.
      std::string why = e->message;
      if (e->parameter == "fetch") why = "must be greater than 0 km (the sea needs open water to grow)";
      // The cascades' resolution is the option fft_size (`resolution` is the scene passes' knob).
      std::string option = e->parameter == "resolution" ? "fft_size" : e->parameter;
      return NodeSpec::OptionProblem{option, why};
    }
    return std::nullopt;
  };
  s.isSource = true;
  s.isUniformSource = true;  // the same sea for every vertex and pixel: no varying carries it
  s.recomputeInFragment = true;
  // A name, so the body writer declares nothing: the readers name the maps
  // themselves.
  // A name no line declares: the readers take the ocean's maps from the planner
  // (EmitContext::oceanMap), never this value, so the writer keeps it as an alias.
  s.emit = [](EmitContext& ctx) { ctx.output(0, GlslExpr::name("ocean_handle")); };
  s.eval = [](EvalContext& ctx) {
    Value v = Value::ofType(Type::Ocean);
    v[0] = oceanref::registerOcean(ctx.options<ocean::OceanSettings>());
    ctx.output(0, v);
  };
  s.tolerance = 0;
  return s;
}

}  // namespace wg::nodes
