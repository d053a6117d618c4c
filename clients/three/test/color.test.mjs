// Checks of the client's colour pipeline that need no browser (node --test): the view a
// manifest states, the render options over it, the output pass built from the scene
// description's own shader, and the RGBA8 fallback said once. The fixtures are those of
// api.test.mjs (WG_THREE_FIXTURES, written by tests/ecosystem/three_client_test.cpp).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import * as THREE from 'three';
import { WaterGraph, WaterGraphError, TONE_MAPPERS } from '../watergraph-three.js';
import { checkSceneDescription } from '../watergraph-passes.js';
import { manifestView, renderView, OutputTransform } from '../watergraph-output.js';

const dir = process.env.WG_THREE_FIXTURES;
const read = (f) => {
  assert.ok(dir, 'WG_THREE_FIXTURES is not set');
  return readFileSync(path.join(dir, f), 'utf8');
};
const graph = () => {
  const manifest = JSON.parse(read('three_environment.manifest.json'));
  const form = (stage) => ({ glsl_version: manifest.three[stage].glsl_version, body: read(manifest.three[stage].body_file) });
  return { manifest, shaders: { vertex: form('vertex'), fragment: form('fragment') } };
};
const description = () => JSON.parse(read('scene.json'));
const refused = (fn, words) => assert.throws(fn, (e) => e instanceof WaterGraphError && e.message.includes(words),
  `expected a WaterGraphError with "${words}"`);

test("the manifest's view is the graph's default, checked as the runtime reads it", () => {
  const { manifest } = graph();
  assert.deepEqual(manifest.color, { frame: 'linear', primaries: 'bt709', view: { exposure: 0, output: 'srgb', tonemap: 'none' } });
  assert.deepEqual(manifestView(manifest), { toneMapping: 'none', exposure: 0 });
  const { color, ...older } = manifest;  // written before "color" existed
  assert.deepEqual(manifestView(older), { toneMapping: 'none', exposure: 0 });
  const withView = (view) => ({ ...manifest, color: { ...color, view: { ...color.view, ...view } } });
  assert.deepEqual(manifestView(withView({ tonemap: 'agx', exposure: -1.5 })), { toneMapping: 'agx', exposure: -1.5 });
  refused(() => manifestView(withView({ tonemap: 'filmic' })), `"tonemap" must be one of none, aces, agx, neutral (got 'filmic')`);
  refused(() => manifestView(withView({ exposure: 21 })), '"exposure" must be a finite number of EV in [-20, 20]');
  refused(() => manifestView(withView({ output: 'rec2020' })), 'has an "output" other than "srgb"');
  refused(() => manifestView({ ...manifest, color: { ...color, frame: 'display' } }), 'has a "frame" other than "linear"');
  refused(() => manifestView({ ...manifest, color: { ...color, primaries: 'p3' } }), 'has "primaries" other than "bt709"');
  refused(() => manifestView({ ...manifest, color: { ...color, gamut: 'wide' } }), 'has an unknown member "gamut"');
  refused(() => manifestView({ ...manifest, color: 'srgb' }), 'is not an object');
  // The WaterGraph refuses such a manifest at once, with or without a description.
  refused(() => new WaterGraph({ ...graph(), manifest: withView({ tonemap: 'reinhard' }), description: description() }),
    "graph 'three_environment': the manifest's \"color\"'s view \"tonemap\" must be one of");
});

test('the render options override the view; a bad one is an error naming it', () => {
  const view = { toneMapping: 'aces', exposure: 1 };
  assert.deepEqual(renderView(view), view);
  assert.deepEqual(renderView(view, { exposure: -2 }), { toneMapping: 'aces', exposure: -2 });
  assert.deepEqual(renderView(view, { toneMapping: 'neutral' }), { toneMapping: 'neutral', exposure: 1 });
  refused(() => renderView(view, { toneMapping: 'ACES' }), "the render option toneMapping must be one of none, aces, agx, neutral (got 'ACES')");
  for (const bad of [NaN, Infinity, -20.5, '1'])
    refused(() => renderView(view, { exposure: bad }), 'the render option exposure must be a finite number of EV in [-20, 20]');

  // Through WaterGraph.render, before anything is drawn (no renderer is needed to refuse).
  const water = new WaterGraph({ ...graph(), description: description() });
  assert.deepEqual(water.view, { toneMapping: 'none', exposure: 0 });
  const scene = new THREE.Scene(), camera = new THREE.PerspectiveCamera();
  refused(() => water.render(null, scene, camera, null, { toneMapping: 'filmic' }), 'the render option toneMapping');
  refused(() => water.render(null, scene, camera, null, { exposure: 40 }), 'the render option exposure');
  refused(() => water.render(null, scene, camera, null, { tonemap: 'aces' }), "unknown render option 'tonemap'");
  refused(() => water.render(null, scene, camera, null, { outputTransform: 'no' }), 'outputTransform must be true or false');
  refused(() => water.render(null, scene, camera, new THREE.WebGLRenderTarget(4, 4), { outputTransform: false }),
    'read the linear frame from water.frameTarget');
  // Without a description there is no output transform to take the options.
  const plain = new WaterGraph({ ...graph(), resources: { environment: new THREE.CubeTexture() } });
  assert.equal(plain.frameFormat, null);
  refused(() => plain.render(null, scene, camera, null, { exposure: 1 }), 'comes with a scene description');
});

test("the output pass is the description's own shader, with the runtime's uniforms", () => {
  const d = description();
  const pass = new OutputTransform(d);
  assert.equal(pass.material.fragmentShader, d.three.shaders.output_transform_fragment.body);
  assert.equal(pass.material.vertexShader, d.three.shaders.fullscreen_vertex.body);
  assert.equal(pass.material.glslVersion, THREE.GLSL3);
  assert.equal(pass.material.blending, THREE.NoBlending);
  assert.equal(pass.material.depthTest, false);
  assert.deepEqual(d.color.tone_mappers, TONE_MAPPERS);
  for (const [i, toneMapping] of TONE_MAPPERS.entries()) {
    pass.setView({ toneMapping, exposure: -2.5 });
    assert.equal(pass.uniforms.u_tone_mapper.value, i);
    assert.equal(Math.fround(pass.uniforms.u_exposure_scale.value), Math.fround(2 ** -2.5));
  }
  pass.setView({ toneMapping: 'none', exposure: 3 });
  assert.equal(pass.uniforms.u_exposure_scale.value, 8);
});

test('a description of another format or colour contract is refused', () => {
  refused(() => checkSceneDescription({ ...description(), format: 'watergraph-scene-1' }), 'not a scene description of format watergraph-scene-2');
  const d = description();
  refused(() => checkSceneDescription({ ...d, color: { ...d.color, frame_format: 'rgba32f' } }), "frame_format 'rgba32f'");
  refused(() => checkSceneDescription({ ...d, color: { ...d.color, tone_mappers: ['none', 'aces'] } }), 'lacks some of the tone mappers');
  const { output_transform_fragment, ...shaders } = d.three.shaders;
  refused(() => checkSceneDescription({ ...d, three: { shaders } }), 'no shader "output_transform_fragment"');
  const { three, ...withoutForms } = d;
  refused(() => checkSceneDescription(withoutForms), 'the scene description has no "three"');
});

test('without renderable half floats the targets fall back to RGBA8, said once', () => {
  const water = new WaterGraph({ ...graph(), description: description() });
  assert.equal(water.frameFormat, 'rgba16f');
  assert.equal(water.frameFallback, null);
  assert.equal(water.frameTarget.texture.type, THREE.HalfFloatType);
  assert.equal(water.passes.targets.environment.texture.type, THREE.HalfFloatType);
  const warned = [];
  const warn = console.warn;
  console.warn = (m) => warned.push(m);
  try {
    const halfOnly = { extensions: { has: (name) => name === 'EXT_color_buffer_half_float' } };
    assert.equal(water.passes.configure(halfOnly), false);  // half floats render: nothing changes
    assert.equal(water.frameFormat, 'rgba16f');
    const none = { extensions: { has: () => false } };
    assert.equal(water.passes.configure(none), true);
    assert.equal(water.passes.configure(none), false);
    assert.equal(water.frameFormat, 'rgba8');
    assert.match(water.frameFallback, /neither EXT_color_buffer_float nor EXT_color_buffer_half_float/);
    assert.equal(water.frameTarget.texture.type, THREE.UnsignedByteType);
    assert.equal(water.passes.targets.environment.texture.type, THREE.UnsignedByteType);
    assert.equal(warned.length, 1);
    assert.equal(warned[0], `watergraph: ${water.frameFallback}`);
  } finally {
    console.warn = warn;
  }
});
