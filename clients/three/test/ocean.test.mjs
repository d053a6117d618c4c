// The spectral ocean's plumbing without a browser (node --test): the pass order of a filtered
// and an unfiltered cascade, the pyramid's levels, and the raw WebGL of a filtered cascade's
// pyramid (watergraph-ocean-pyramid.js) against a context that records its calls.
import assert from 'node:assert/strict';
import { test } from 'node:test';
import * as THREE from 'three';
import { cascadePasses, OCEAN_MAPS, OceanSimulation } from '../watergraph-ocean.js';
import { downsampleDraws, OceanPyramid, PyramidPrograms, pyramidLevels } from '../watergraph-ocean-pyramid.js';
import { WaterGraphError } from '../watergraph-error.js';

test('a pyramid has log2 N + 1 levels, drawn from the top down', () => {
  assert.deepEqual([1, 2, 16, 64, 256, 512].map(pyramidLevels), [1, 2, 5, 7, 9, 10]);
  for (const bad of [0, 3, 48, 2.5, -4]) assert.throws(() => pyramidLevels(bad), WaterGraphError);
  assert.deepEqual(downsampleDraws(8), [{ level: 1, source: 0, size: 4 }, { level: 2, source: 1, size: 2 }, { level: 3, source: 2, size: 1 }]);
  assert.deepEqual(downsampleDraws(1), []);
});

test('a filtered cascade packs three maps, then downsamples once per level; an unfiltered one never', () => {
  const names = (plan) => plan.map((p) => p.shader);
  const stages = (shader, n) => Array(2 * Math.log2(n)).fill(shader);
  assert.deepEqual(names(cascadePasses(16, { slopes: true, filtered: true })),
    ['ocean_evolve', ...stages('ocean_stockham', 16), 'ocean_pack_filtered', ...Array(4).fill('ocean_downsample')]);
  // The filter needs the slopes' transform even where no shader reads the slope map itself.
  assert.deepEqual(names(cascadePasses(16, { slopes: false, filtered: true })), names(cascadePasses(16, { slopes: true, filtered: true })));
  assert.deepEqual(names(cascadePasses(16, { slopes: true, filtered: false })), ['ocean_evolve', ...stages('ocean_stockham', 16), 'ocean_pack']);
  assert.deepEqual(names(cascadePasses(16, { slopes: false, filtered: false })),
    ['ocean_evolve_displacement', ...stages('ocean_stockham_single', 16), 'ocean_pack_displacement']);
  const down = cascadePasses(64, { slopes: true, filtered: true }).filter((p) => p.shader === 'ocean_downsample');
  assert.deepEqual(down.map((p) => [p.level, p.source, p.size]), [[1, 0, 32], [2, 1, 16], [3, 2, 8], [4, 3, 4], [5, 4, 2], [6, 5, 1]]);
  // The Stockham stages: log2 N horizontal, then log2 N vertical, ns doubling.
  const stockham = cascadePasses(8, { slopes: true, filtered: true }).filter((p) => p.shader === 'ocean_stockham');
  assert.deepEqual(stockham.map((p) => [p.vertical, p.ns]), [[0, 1], [0, 2], [0, 4], [1, 1], [1, 2], [1, 4]]);
});

// An ocean module and manifest of oceans of two cascades each (16 and 8 texels): `oceans`
// lists each ocean's "filtered" (the compiler's value) and the maps its textures read
// ([cascade, map] pairs).
function oceanOf(oceans) {
  const sizes = [16, 8];
  const module = {
    oceans: oceans.map((_, o) => ({
      node: `sea${o}`, tileLengths: [100, 10], sizes, dk: [0.06, 0.6], choppiness: 1, foam: { cascades: 0 },
      cascades: () => sizes.map((n) => ({ h0: new Float32Array(4 * n * n), frequency: new Uint32Array(n * n) })),
    })),
    twiddles: (n) => new Float32Array(n),
    phaseTau: (t) => t,
  };
  const manifest = { graph: 'g', oceans: oceans.map(({ filtered }, o) => ({ node: `sea${o}`, filtered })),
    textures: oceans.flatMap(({ maps }, o) => maps.map(([cascade, map]) => ({ name: `t${o}_${map}${cascade}`, ocean: { ocean: o, cascade, map } }))) };
  return new OceanSimulation(manifest, module, { shaders: {} });
}

test('an ocean the manifest marks filtered keeps pyramids in every cascade, and map() gives their textures', () => {
  assert.deepEqual(OCEAN_MAPS, ['displacement', 'slopes', 'foam', 'moments']);
  const sim = oceanOf([{ filtered: true, maps: [[0, 'displacement'], [0, 'slopes'], [0, 'moments'], [1, 'moments']] },
    { filtered: false, maps: [[1, 'displacement'], [1, 'slopes']] }]);
  const [filtered, alsoFiltered] = sim.oceans[0].cascades, plain = sim.oceans[1].cascades[1];
  assert.equal(filtered.filtered, true);
  assert.equal(alsoFiltered.filtered, true);
  assert.equal(plain.filtered, false);
  assert.equal(filtered.plan.filter((p) => p.shader === 'ocean_downsample').length, 4);
  assert.equal(alsoFiltered.plan.filter((p) => p.shader === 'ocean_downsample').length, 3);
  assert.equal(plain.plan.filter((p) => p.shader === 'ocean_downsample').length, 0);
  const maps = ['displacement', 'slopes', 'moments'].map((map) => sim.map({ ocean: 0, cascade: 0, map }));
  assert.ok(maps.every((t) => t.isExternalTexture));
  assert.equal(new Set(maps).size, 3);
  assert.ok(sim.map({ ocean: 1, cascade: 1, map: 'slopes' }).isRenderTargetTexture);
  assert.throws(() => sim.map({ ocean: 1, cascade: 1, map: 'moments' }), /moments map is not computed/);
  // Filtered with no shader reading its slope map: the slopes are transformed all the same
  // (ocean_pack_filtered reads both spectra).
  const moments = oceanOf([{ filtered: true, maps: [[0, 'moments']] }]).oceans[0].cascades[0];
  assert.equal(moments.filtered, true);
  assert.equal(moments.spectra[0].textures.length, 2);
  // The value decides, not the list: a moments map listed for an ocean not marked filtered
  // (which checkManifest refuses) makes no pyramid.
  assert.equal(oceanOf([{ filtered: false, maps: [[0, 'moments']] }]).oceans[0].cascades[0].filtered, false);
});

// A WebGL 2 context that records every call: constants are numbers (the two the code adds
// to, COLOR_ATTACHMENT0 and TEXTURE0, at their real values), create* returns a new object.
function recordingContext() {
  const calls = [], constants = new Map([['COLOR_ATTACHMENT0', 0x8ce0], ['TEXTURE0', 0x84c0]]);
  let next = 1;
  const gl = new Proxy({}, {
    get(_, key) {
      if (key === 'calls') return calls;
      if (typeof key !== 'string') return undefined;
      if (/^[A-Z][A-Z0-9_]*$/.test(key)) {
        if (!constants.has(key)) constants.set(key, 0x10000 + constants.size);
        return constants.get(key);
      }
      return (...args) => {
        calls.push([key, ...args]);
        if (key.startsWith('create')) return { kind: key.slice(6), id: next++ };
        if (key === 'checkFramebufferStatus') return constants.get('FRAMEBUFFER_COMPLETE') ?? gl.FRAMEBUFFER_COMPLETE;
        if (key === 'getShaderParameter' || key === 'getProgramParameter') return true;
        if (key === 'getUniformLocation') return args[1];
        return undefined;
      };
    },
  });
  return gl;
}

// Replays the recorded calls as a GL state machine and returns each draw: its program, its
// viewport, the (texture, level) of each colour attachment and each sampled texture's
// visible levels [base, max] when it ran.
function drawsOf(gl) {
  const fbAttachments = new Map(), params = new Map(), units = new Map();
  let fb = null, bound = null, unit = 0, program = null, viewport = null;
  const draws = [];
  for (const [name, ...a] of gl.calls) {
    if (name === 'bindFramebuffer') fb = a[1];
    else if (name === 'framebufferTexture2D') {
      if (!fbAttachments.has(fb)) fbAttachments.set(fb, []);
      fbAttachments.get(fb)[a[1] - gl.COLOR_ATTACHMENT0] = { texture: a[3], level: a[4] };
    } else if (name === 'activeTexture') unit = a[0] - gl.TEXTURE0;
    else if (name === 'bindTexture') { bound = a[1]; units.set(unit, a[1]); }
    else if (name === 'texParameteri') {
      if (!params.has(bound)) params.set(bound, { base: 0, max: 1000 });
      if (a[1] === gl.TEXTURE_BASE_LEVEL) params.get(bound).base = a[2];
      if (a[1] === gl.TEXTURE_MAX_LEVEL) params.get(bound).max = a[2];
    } else if (name === 'useProgram') program = a[0];
    else if (name === 'viewport') viewport = a[2];
    else if (name === 'drawArrays') {
      draws.push({ program, size: viewport, attachments: fbAttachments.get(fb),
        sampled: [0, 1].map((u) => ({ texture: units.get(u), ...(params.get(units.get(u)) ?? { base: 0, max: 1000 }) })) });
    }
  }
  return { draws, params };
}

test('the pyramid: pack into level 0, then each level drawn from the one above alone, every level visible after', () => {
  const gl = recordingContext();
  let resets = 0;
  const a = { name: 'spectrum a' }, b = { name: 'spectrum b' };
  const renderer = { getContext: () => gl, properties: { get: (t) => ({ __webglTexture: t.name }) }, resetState: () => { ++resets; } };
  const description = { shaders: { fullscreen_vertex: 'v', ocean_pack_filtered: 'p', ocean_downsample: 'd' } };
  const programs = new PyramidPrograms(description), n = 8, pyramid = new OceanPyramid(n);
  pyramid.update(renderer, programs, a, b, 0.75);
  const { draws, params } = drawsOf(gl);
  const [displacement, slopes, moments] = pyramid.maps;
  assert.deepEqual(draws.map((d) => d.size), [8, 4, 2, 1]);
  // The pack: the spectra in, level 0 of the three maps out, lambda set.
  assert.equal(draws[0].program, programs.pack);
  assert.deepEqual(draws[0].sampled.map((s) => s.texture), ['spectrum a', 'spectrum b']);
  assert.deepEqual(draws[0].attachments, [displacement, slopes, moments].map((texture) => ({ texture, level: 0 })));
  assert.ok(gl.calls.some(([name, , value]) => name === 'uniform1f' && value === 0.75));
  for (let l = 1; l <= 3; ++l) {
    const d = draws[l];
    assert.equal(d.program, programs.downsample);
    assert.deepEqual(d.attachments, [{ texture: slopes, level: l }, { texture: moments, level: l }]);
    // Each sampler shows level l - 1 alone: its level 0 is the level above, and the level
    // drawn is outside what it samples (no feedback loop).
    assert.deepEqual(d.sampled, [{ texture: slopes, base: l - 1, max: l - 1 }, { texture: moments, base: l - 1, max: l - 1 }]);
  }
  // After the chain the water shader sees all L + 1 levels; three.js forgets its cached state.
  assert.deepEqual(params.get(slopes), { base: 0, max: 3 });
  assert.deepEqual(params.get(moments), { base: 0, max: 3 });
  assert.equal(resets, 1);
  // Storage: the displacement one level, the slope and moments maps four (8, 4, 2, 1).
  const storage = gl.calls.filter(([name]) => name === 'texStorage2D').map(([, , levels, , w, h]) => [levels, w, h]);
  assert.deepEqual(storage, [[1, 8, 8], [4, 8, 8], [4, 8, 8]]);
  // The three.js textures the water binds wrap them.
  assert.deepEqual(pyramid.textures.map((t) => t.sourceTexture), [displacement, slopes, moments]);
  assert.ok(pyramid.textures[0] instanceof THREE.ExternalTexture);
});

test('a pass shader missing from the description is a clear error', () => {
  const gl = recordingContext();
  const renderer = { getContext: () => gl, properties: { get: () => ({}) }, resetState: () => {} };
  const programs = new PyramidPrograms({ shaders: { fullscreen_vertex: 'v', ocean_pack_filtered: 'p' } });
  assert.throws(() => new OceanPyramid(4).update(renderer, programs, {}, {}, 1), /no shader 'ocean_downsample'/);
});
