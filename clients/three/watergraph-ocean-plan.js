// The spectral ocean simulation's plan, shared by both web clients: which maps each cascade
// of a manifest's oceans computes and the passes that make them, in the runtime's order
// (runtime/ocean_gpu_cascade.cpp). The three.js client (watergraph-ocean.js,
// watergraph-ocean-pyramid.js) and the WebGPU runner (clients/webgpu/watergraph-webgpu-ocean.js,
// which imports this file as ../three/watergraph-ocean-plan.js, served as /three/ beside it)
// run these passes each with its own API. No three.js and no WebGPU here: plain values.
import { WaterGraphError } from './watergraph-error.js';

// The map names of a manifest texture's "ocean" (core/ocean_settings.h kOceanMapNames).
export const OCEAN_MAPS = ['displacement', 'slopes', 'foam', 'moments'];

// The levels of an N x N pyramid down to 1 x 1: log2 N + 1.
export function pyramidLevels(n) {
  if (!Number.isInteger(n) || n < 1 || (n & (n - 1)) !== 0)
    throw new WaterGraphError(`an ocean cascade's resolution must be a power of two (got ${n})`);
  return Math.log2(n) + 1;
}

// The downsample draws of an N x N pyramid in order: level l (1..L) of size N >> l from
// level l - 1.
export function downsampleDraws(n) {
  const draws = [];
  for (let level = 1; level < pyramidLevels(n); ++level) draws.push({ level, source: level - 1, size: n >> level });
  return draws;
}

// What cascade `c` of ocean `o` computes: `slopes` and `foam` where a shader samples them
// (a manifest texture names the map), `filtered` for every cascade of an ocean the compiler
// wrote "filtered": true (a shader reads its moments maps: its slope and moments maps carry
// mip pyramids, and its slopes are computed whether read or not).
export function cascadeMaps(manifest, o, c) {
  const read = (map) => (manifest.textures ?? []).some((t) =>
    t.ocean && t.ocean.ocean === o && t.ocean.cascade === c && t.ocean.map === map);
  const filtered = manifest.oceans[o].filtered === true;
  return { slopes: read('slopes') || filtered, foam: read('foam'), filtered };
}

// The passes of one cascade's maps in order: the evolution, 2 log2 N Stockham stages, the
// packing, and for a filtered cascade one ocean_downsample per pyramid level l = 1..L
// (level l, N >> l square, from level l - 1). `slopes`: the slope map is computed (a
// filtered cascade always computes it).
export function cascadePasses(n, { slopes, filtered }) {
  const both = slopes || filtered;
  const passes = [{ shader: both ? 'ocean_evolve' : 'ocean_evolve_displacement' }];
  for (let vertical = 0; vertical < 2; ++vertical)
    for (let ns = 1; ns < n; ns *= 2) passes.push({ shader: both ? 'ocean_stockham' : 'ocean_stockham_single', ns, vertical });
  passes.push({ shader: filtered ? 'ocean_pack_filtered' : both ? 'ocean_pack' : 'ocean_pack_displacement' });
  if (filtered) for (const d of downsampleDraws(n)) passes.push({ shader: 'ocean_downsample', ...d });
  return passes;
}
