// The web clients' ocean module (`compile --target es300` writes <graph>.ocean.js beside the
// manifest, codegen/ocean_module_js.h) run under node against the compiler's own values:
// each cascade's packed h0 (h0(k), conj(h0(-k)) in float32) against what the GL runtime
// uploads (runtime/ocean_gpu_cascade.cpp, from core/ocean_fft_reference.h), the frequency
// indices bit for bit, the twiddles, u_dk, the 32-bit time phase (ocean::loopFraction) and
// the foam's constants and clock (core/ocean_foam.h) at ordinary, huge and non-finite times.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "eco_support.h"
#include "core/ocean_settings.h"
#include "query_samples.h"

namespace wg::eco {
namespace {

using nlohmann::json;

// The times the clocks are read at: ordinary, on a foam step, past the 65536 s loop, huge,
// negative and not finite.
const std::vector<std::string> kTimes = {"0", "3.5", "1.4", "0.2", "65539.25", "1e6", "-2.25", "NaN", "Infinity"};

std::vector<char> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <typename T>
std::vector<T> readArray(const std::string& path) {
  std::vector<char> bytes = readBytes(path);
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

// Floats apart in units in the last place (same sign assumed; 0 and -0 are 0 apart).
int64_t ulpsApart(float a, float b) {
  if (a == b) return 0;
  int32_t ia, ib;
  std::memcpy(&ia, &a, 4);
  std::memcpy(&ib, &b, 4);
  if ((ia < 0) != (ib < 0)) return INT64_MAX;
  return std::llabs(static_cast<int64_t>(ia) - ib);
}

ocean::OceanSettings openOceanSettings() {
  std::string errors;
  auto program = test::compileFile(test::sourcePath("graphs/open_ocean.json"), &errors);
  EXPECT_TRUE(program) << errors;
  for (const Op& op : program->ops)
    if (op.spec->type == "ocean_spectrum") return op.parsedOptions->as<ocean::OceanSettings>();
  ADD_FAILURE() << "open_ocean has no ocean_spectrum";
  return {};
}

TEST(OceanModule, HoldsTheCompilersH0PhasesAndFoamClockForOpenOcean) {
  TempDir dir("wg_ocean_module_");
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("graphs/open_ocean.json")) + " -o " +
                      test::shellQuote(dir.path()) + " --target es300 --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  const json manifest = json::parse(test::readFile(dir / "open_ocean.manifest.json"));
  ASSERT_EQ(manifest["oceans"].size(), 1u);
  EXPECT_EQ(manifest["oceans"][0]["module"], "open_ocean.ocean.js");

  std::string times;
  for (const auto& t : kTimes) times += (times.empty() ? "" : ", ") + t;
  test::writeFile(dir / "package.json", "{\"type\": \"module\"}\n");
  test::writeFile(dir / "main.js", R"(import * as m from './open_ocean.ocean.js';
import { writeFileSync } from 'node:fs';
const o = m.oceans[0];
o.cascades().forEach((c, i) => {
  writeFileSync(`h0_${i}.bin`, Buffer.from(c.h0.buffer));
  writeFileSync(`frequency_${i}.bin`, Buffer.from(c.frequency.buffer));
});
writeFileSync('twiddle.bin', Buffer.from(m.twiddles(o.sizes[0]).buffer));
const times = [)" + times + R"(];
console.log(JSON.stringify({node: o.node, sizes: o.sizes, tileLengths: o.tileLengths, dk: o.dk,
  choppiness: o.choppiness, foam: o.foam, tau: times.map(m.phaseTau),
  step: times.map((t) => m.foamStepIndex(o.foam, t)), fraction: times.map((t) => m.foamFraction(o.foam, t))}));
)");
  CmdResult r = sh("cd " + test::shellQuote(dir.path()) + " && timeout 60 node main.js");
  ASSERT_EQ(r.exit, 0) << r.err;
  const json got = json::parse(r.out);

  const ocean::OceanSettings s = openOceanSettings();
  const int n = ocean::cascadeResolution(s.cascades, 0);  // the twiddles' N
  EXPECT_EQ(got["node"], "sea");
  ASSERT_EQ(got["sizes"].size(), s.cascades.tileLengths.size());
  for (size_t k = 0; k < s.cascades.tileLengths.size(); ++k)
    EXPECT_EQ(got["sizes"][k], ocean::cascadeResolution(s.cascades, k)) << "cascade " << k;
  EXPECT_EQ(got["choppiness"].get<double>(), s.cascades.choppiness);
  ASSERT_EQ(got["tileLengths"].size(), s.cascades.tileLengths.size());
  for (size_t k = 0; k < s.cascades.tileLengths.size(); ++k) {
    EXPECT_EQ(got["tileLengths"][k].get<double>(), s.cascades.tileLengths[k]);
    EXPECT_EQ(got["dk"][k].get<double>(), 2.0 * ocean::kPi / s.cascades.tileLengths[k]);
  }
  const json& foam = got["foam"];
  EXPECT_EQ(foam["cascades"], s.foam.cascades);
  EXPECT_EQ(foam["step"].get<double>(), s.foam.step);
  EXPECT_EQ(foam["keep"].get<double>(), ocean::foamKeep(s.foam));
  EXPECT_EQ(foam["gain"].get<double>(), ocean::foamGain(s.foam));
  EXPECT_EQ(foam["threshold"].get<double>(), s.foam.threshold);
  EXPECT_EQ(foam["historySteps"], ocean::historySteps(s.foam));
  for (size_t i = 0; i < kTimes.size(); ++i) {
    const double t = std::strtod(kTimes[i].c_str(), nullptr);
    EXPECT_EQ(got["tau"][i].get<double>(), ocean::loopFraction(t)) << "t = " << kTimes[i];
    EXPECT_EQ(got["step"][i].get<double>(), static_cast<double>(ocean::stepIndex(s.foam, t))) << "t = " << kTimes[i];
    EXPECT_EQ(got["fraction"][i].get<double>(), ocean::foamFraction(s.foam, t)) << "t = " << kTimes[i];
  }

  // The twiddles as the runtime rounds them (double cos/sin, then float).
  const auto twiddle = readArray<float>(dir / "twiddle.bin");
  ASSERT_EQ(twiddle.size(), static_cast<size_t>(n));
  for (int m = 0; m < n / 2; ++m) {
    const double angle = 2.0 * ocean::kPi * m / n;
    EXPECT_LE(ulpsApart(twiddle[2 * m], static_cast<float>(std::cos(angle))), 1) << m;
    EXPECT_LE(ulpsApart(twiddle[2 * m + 1], static_cast<float>(std::sin(angle))), 1) << m;
  }

  // h0 as the runtime uploads it: the JavaScript's doubles agree with the compiler's to a
  // few double ulps (QueryJs holds them to 1e-12), so rounded to float32 a value is the
  // runtime's or, where the double lies within those ulps of a float halfway point, its
  // neighbour; and no bin the compiler leaves empty is filled.
  int64_t values = 0, differing = 0;
  for (size_t k = 0; k < s.cascades.tileLengths.size(); ++k) {
    const ocean::OceanCascade expected = ocean::initialCascade(s.spectrum, s.cascades, static_cast<int>(k));
    const auto h0 = readArray<float>(dir / ("h0_" + std::to_string(k) + ".bin"));
    const auto frequency = readArray<uint32_t>(dir / ("frequency_" + std::to_string(k) + ".bin"));
    ASSERT_EQ(h0.size(), expected.h0.size() * 4);
    ASSERT_EQ(frequency, expected.frequency) << "cascade " << k;
    const int nk = expected.resolution;
    for (int iz = 0; iz < nk; ++iz)
      for (int ix = 0; ix < nk; ++ix) {
        const size_t i = static_cast<size_t>(iz) * nk + ix;
        const size_t mirror = static_cast<size_t>((nk - iz) % nk) * nk + static_cast<size_t>((nk - ix) % nk);
        const std::complex<double> a = expected.h0[i], b = std::conj(expected.h0[mirror]);
        const float want[4] = {static_cast<float>(a.real()), static_cast<float>(a.imag()), static_cast<float>(b.real()),
                               static_cast<float>(b.imag())};
        for (int ch = 0; ch < 4; ++ch, ++values) {
          const float g = h0[i * 4 + ch];
          if (g != want[ch]) ++differing;
          EXPECT_EQ(g == 0.0f, want[ch] == 0.0f) << "cascade " << k << " bin " << ix << "," << iz << " channel " << ch;
          ASSERT_LE(ulpsApart(g, want[ch]), 1) << "cascade " << k << " bin " << ix << "," << iz << " channel " << ch
                                               << ": " << g << " against " << want[ch];
        }
      }
  }
  std::printf("ocean module h0: %lld of %lld float32 values equal the runtime's upload, %lld one ulp apart\n",
              static_cast<long long>(values - differing), static_cast<long long>(values),
              static_cast<long long>(differing));
}

// A resolution per cascade (cascade_sizes): the module gives each cascade its own N, and
// packs each cascade's h0 and frequencies on that N x N grid (the clients size the cascade's
// textures, twiddles and foam from it).
TEST(OceanModule, GivesEachCascadeItsOwnSize) {
  TempDir dir("wg_ocean_module_sizes_");
  test::writeFile(dir / "sizes.json", R"({"version": 1, "name": "sizes", "nodes": [
      {"id": "sea", "type": "ocean_spectrum", "options": {"tile_lengths": [120, 24, 5], "cascade_sizes": [16, 32, 64]}},
      {"id": "moved", "type": "ocean_displacement", "inputs": {"ocean": "sea.ocean"}}],
      "outputs": {"vertex": {"position": "moved.position"}, "fragment": {"color": "moved.normal"}}})");
  CmdResult c = wgRun("compile " + test::shellQuote(dir / "sizes.json") + " -o " +
                      test::shellQuote(dir.path()) + " --target es300 --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  test::writeFile(dir / "package.json", "{\"type\": \"module\"}\n");
  test::writeFile(dir / "main.js", R"(import * as m from './sizes.ocean.js';
import { writeFileSync } from 'node:fs';
const o = m.oceans[0];
o.cascades().forEach((c, i) => writeFileSync(`h0_${i}.bin`, Buffer.from(c.h0.buffer)));
console.log(JSON.stringify({sizes: o.sizes, frequencies: o.cascades().map((c) => c.frequency.length)}));
)");
  CmdResult r = sh("cd " + test::shellQuote(dir.path()) + " && timeout 60 node main.js");
  ASSERT_EQ(r.exit, 0) << r.err;
  const json got = json::parse(r.out);
  EXPECT_EQ(got["sizes"].dump(), "[16,32,64]");
  ocean::OceanSettings s;
  s.cascades.tileLengths = {120, 24, 5};
  s.cascades.sizes = {16, 32, 64};
  for (int k = 0; k < 3; ++k) {
    const ocean::OceanCascade expected = ocean::initialCascade(s.spectrum, s.cascades, k);
    EXPECT_EQ(got["frequencies"][k].get<size_t>(), expected.frequency.size()) << "cascade " << k;
    const auto h0 = readArray<float>(dir / ("h0_" + std::to_string(k) + ".bin"));
    ASSERT_EQ(h0.size(), expected.h0.size() * 4) << "cascade " << k;
    // Every bin's h0(k) (channels 0 and 1) within one float ulp of the compiler's.
    for (size_t i = 0; i < expected.h0.size(); ++i) {
      ASSERT_LE(ulpsApart(h0[i * 4], static_cast<float>(expected.h0[i].real())), 1) << "cascade " << k << " bin " << i;
      ASSERT_LE(ulpsApart(h0[i * 4 + 1], static_cast<float>(expected.h0[i].imag())), 1) << "cascade " << k << " bin " << i;
    }
  }
}

// A compile with no web target writes no module, and its manifest names none.
TEST(OceanModule, IsWrittenOnlyWithAWebTarget) {
  TempDir dir("wg_ocean_module_");
  CmdResult c = wgRun("compile " + test::shellQuote(test::sourcePath("graphs/open_ocean.json")) + " -o " +
                      test::shellQuote(dir.path()) + " --target glsl330 --quiet");
  ASSERT_EQ(c.exit, 0) << c.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "open_ocean.ocean.js"));
  const json manifest = json::parse(test::readFile(dir / "open_ocean.manifest.json"));
  EXPECT_FALSE(manifest["oceans"][0].contains("module"));
}

}  // namespace
}  // namespace wg::eco
