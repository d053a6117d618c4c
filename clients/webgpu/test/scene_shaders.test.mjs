// The runtime's shaders as the WebGPU runner takes them (watergraph-webgpu-scene-shaders.js),
// without a browser: node --test, with WG_SCENE_DESCRIPTION naming a `watergraph scene` file.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';
import * as naga from 'naga-wasm';
import { locationDefines, sceneShadersWgsl, SceneShaderError, webgpuFormOf } from '../watergraph-webgpu-scene-shaders.js';
import { renderGraph, WebgpuRunnerError } from '../watergraph-webgpu.js';
import { oceanPassesWgsl } from '../watergraph-webgpu-ocean.js';

const description = JSON.parse(readFileSync(process.env.WG_SCENE_DESCRIPTION, 'utf8'));
const gbufferInputs = { v_world_position: 0, v_normal: 1, v_uv: 2 };

test('every runtime shader the passes use becomes a WGSL module naga validates', () => {
  const s = sceneShadersWgsl(description, naga, gbufferInputs);
  assert.deepEqual(Object.keys(s).sort(), ['opaque_fragment', 'opaque_vertex', 'sky_fragment', 'sky_vertex', 'water_gbuffer_fragment']);
  for (const [name, m] of Object.entries(s)) {
    // Reparsed and validated again: what the runner hands WebGPU is valid WGSL.
    naga.validate(naga.parseWgsl(m.wgsl));
    assert.match(m.wgsl, name.endsWith('vertex') ? /@vertex\s+fn main\(/ : /@fragment\s+fn main\(/, name);
  }
  // The G-buffer reads the graph's varyings at the locations given.
  assert.match(s.water_gbuffer_fragment.wgsl, /@location\(0\) v_world_position: vec3<f32>, @location\(1\) v_normal: vec3<f32>, @location\(2\) v_uv: vec2<f32>/);
  // Without deferred water no G-buffer shader is made (no varyings to place it on).
  assert.equal(sceneShadersWgsl(description, naga).water_gbuffer_fragment, undefined);
});

test('the uniform block has the std140 offsets the runner fills', () => {
  const s = sceneShadersWgsl(description, naga);
  assert.deepEqual(s.opaque_vertex.uniforms, { size: 96, members: [
    { name: 'u_view_projection', type: 'mat4', offset: 0 }, { name: 'u_clip_plane', type: 'vec4', offset: 64 },
    { name: 'u_sun_direction', type: 'vec3', offset: 80 }] });
  assert.deepEqual(s.sky_fragment.uniforms, { size: 80, members: [
    { name: 'u_inverse_view_projection', type: 'mat4', offset: 0 }, { name: 'u_sun_direction', type: 'vec3', offset: 64 }] });
  assert.match(s.opaque_vertex.wgsl, /@group\(0\) @binding\(0\)\s*var<uniform>/);
});

test('vertex stages convert clip space as the graph\'s vs_main does; fragments discard on the clipped side', () => {
  // The runtime wrote the WebGPU forms; naga's WGSL of each vertex stage flips y and remaps z.
  const s = sceneShadersWgsl(description, naga);
  for (const name of ['sky_vertex', 'opaque_vertex']) {
    assert.equal(webgpuFormOf(description, name).stage, 'vertex');
    assert.match(s[name].wgsl, /fn wg_runtime_main\(\)/, name);
    assert.match(s[name].wgsl, /-\(_e\d+\.y\)/, name);
  }
  assert.doesNotMatch(s.opaque_fragment.wgsl, /wg_runtime_main/);
  // No clip distances in WebGPU here: the fragment stage discards.
  assert.match(s.opaque_fragment.wgsl, /discard/);
});

test('the G-buffer\'s input locations are naga defines the host sets from the graph\'s varyings', () => {
  const form = webgpuFormOf(description, 'water_gbuffer_fragment');
  assert.deepEqual(locationDefines('g', form, { v_world_position: 4, v_normal: 0, v_uv: 7 }),
    { WG_LOCATION_V_WORLD_POSITION: '4', WG_LOCATION_V_NORMAL: '0', WG_LOCATION_V_UV: '7' });
  const s = sceneShadersWgsl(description, naga, { v_world_position: 4, v_normal: 0, v_uv: 7 });
  assert.match(s.water_gbuffer_fragment.wgsl, /@location\(4\) v_world_position: vec3<f32>, @location\(0\) v_normal: vec3<f32>, @location\(7\) v_uv: vec2<f32>/);
});

test('what the runner cannot take is a SceneShaderError naming it', () => {
  const without = { ...description, webgpu: { shaders: { ...description.webgpu.shaders } } };
  delete without.webgpu.shaders.sky_fragment;
  assert.throws(() => sceneShadersWgsl(without, naga), (e) => e instanceof SceneShaderError && /no WebGPU form of 'sky_fragment'/.test(e.message));
  assert.throws(() => sceneShadersWgsl(description, naga, { v_world_position: 0, v_uv: 2 }),
    (e) => e instanceof SceneShaderError && /water_gbuffer_fragment: no location for its input v_normal/.test(e.message));
  const brokenForm = { ...webgpuFormOf(description, 'opaque_fragment'), glsl: 'void main() { undeclared = 1.0; }\n' };
  const broken = { ...description, webgpu: { shaders: { ...description.webgpu.shaders, opaque_fragment: brokenForm } } };
  assert.throws(() => sceneShadersWgsl(broken, naga), (e) => e instanceof SceneShaderError && /naga could not translate the runtime's opaque_fragment/.test(e.message));
});

test('a manifest with a spectral ocean needs its simulation, refused before any GPU work', async () => {
  const manifest = { graph: 'open_ocean', oceans: [{ node: 'sea', options: {} }], webgpu: {}, passes: ['ocean_simulation', 'water_surface'] };
  await assert.rejects(renderGraph(null, { manifest, plan: { passes: [], targets: [] } }), (e) =>
    e instanceof WebgpuRunnerError && /graph 'open_ocean' has a spectral ocean: give its simulation \(options.ocean\)/.test(e.message));
});

test('the ocean simulation\'s pass shaders become WGSL fragment modules naga validates, with their bindings', () => {
  const passes = oceanPassesWgsl(description, naga);
  assert.equal(Object.keys(passes).length, 11);
  for (const [name, p] of Object.entries(passes)) {
    naga.validate(naga.parseWgsl(p.wgsl));
    assert.match(p.wgsl, /@fragment\s+fn main\(/, name);
    assert.ok(p.wgsl.includes('textureLoad('), name);
  }
  // The bindings come from each form's table: the two-texture stage reads u_b, the single one not.
  assert.deepEqual(passes.ocean_stockham.textures.map((t) => [t.name, t.binding]), [['u_a', 1], ['u_twiddle', 2], ['u_b', 3]]);
  assert.equal(passes.ocean_stockham.samplerBinding, 4);
  assert.equal(passes.ocean_stockham.size, 16);
  assert.deepEqual(passes.ocean_stockham_single.textures.map((t) => t.name), ['u_a', 'u_twiddle']);
  assert.deepEqual(passes.ocean_evolve.uniforms.map((u) => [u.name, u.type, u.offset]), [['u_tau', 'uint', 0], ['u_dk', 'float', 4], ['u_n', 'int', 8]]);
  assert.equal(passes.ocean_evolve.textures.find((t) => t.name === 'u_frequency').sampleType, 'uint');
  // A filtered cascade's passes: the pack's three outputs; the downsample's two samplers and
  // no uniforms (so no uniform block: the pipeline binds none).
  assert.match(passes.ocean_pack_filtered.wgsl, /@location\(2\)/);
  assert.deepEqual(passes.ocean_pack_filtered.textures.map((t) => t.name).sort(), ['u_a', 'u_b']);
  assert.deepEqual(passes.ocean_downsample.textures.map((t) => [t.name, t.sampleType]),
    [['u_slopes', 'unfilterable-float'], ['u_moments', 'unfilterable-float']]);
  assert.deepEqual(passes.ocean_downsample.uniforms, []);
});

