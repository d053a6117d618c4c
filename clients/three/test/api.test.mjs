// Checks of the client's API that need no browser (node --test). WG_THREE_FIXTURES names
// a folder with three_environment.{manifest.json,es300.vert.body,es300.frag.body} compiled from
// tests/ecosystem/data/three_environment.json and scene.json from `watergraph scene`;
// tests/ecosystem/three_client_test.cpp writes them and runs this file.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import * as THREE from 'three';
import { WaterGraph, WaterGraphError, timePhase, createWaterGridGeometry, applySamplerState, sunFromAngles, RESOURCE_PASSES } from '../watergraph-three.js';
import { planPasses, WATER_LAYER } from '../watergraph-passes.js';

const dir = process.env.WG_THREE_FIXTURES;
const graph = () => {
  assert.ok(dir, 'WG_THREE_FIXTURES is not set');
  const read = (f) => readFileSync(path.join(dir, f), 'utf8');
  const manifest = JSON.parse(read('three_environment.manifest.json'));
  const form = (stage) => ({ glsl_version: manifest.three[stage].glsl_version, body: read(manifest.three[stage].body_file) });
  return { manifest, shaders: { vertex: form('vertex'), fragment: form('fragment') } };
};

const description = () => JSON.parse(readFileSync(path.join(dir, 'scene.json'), 'utf8'));

test('without a scene description, a pass the client does not render is an error naming it', () => {
  assert.throws(() => new WaterGraph(graph()), (e) => e instanceof WaterGraphError &&
    e.message.includes("graph 'three_environment' needs render passes the three.js client does not provide: " +
      'environment_cubemap (resource environment: pass it in options.resources)'));
});

test('the stages are forms (a version and a body), never whole texts the client would cut', () => {
  const { manifest, shaders } = graph();
  const refused = (g, words) => assert.throws(() => new WaterGraph({ ...g, resources: { environment: new THREE.CubeTexture() } }),
    (e) => e instanceof WaterGraphError && e.message.includes(words), words);
  refused({ manifest, vertexShader: shaders.vertex.body, fragmentShader: shaders.fragment.body }, 'takes the stages as `shaders: {vertex, fragment}`');
  refused({ manifest, shaders: { vertex: shaders.vertex } }, 'shaders.fragment has no form for three.js');
  refused({ manifest, shaders: { ...shaders, vertex: { ...shaders.vertex, glsl_version: '100' } } }, 'shaders.vertex is GLSL 100');
});

test('a resource the application renders is bound, if its sampler type fits', () => {
  const cube = new THREE.CubeTexture();
  const water = new WaterGraph({ ...graph(), resources: { environment: cube } });
  assert.equal(water.uniforms.u_environment.value, cube);
  // The stages' bodies as compile wrote them: the version line is three.js's (glslVersion).
  assert.equal(water.material.glslVersion, THREE.GLSL3);
  assert.equal(water.material.vertexShader, graph().shaders.vertex.body);
  assert.equal(water.material.fragmentShader, graph().shaders.fragment.body);
  assert.throws(() => new WaterGraph({ ...graph(), resources: { environment: new THREE.Texture() } }),
    /u_environment is a samplerCube, but the texture given for it is not a cube texture/);
});

test('update() sets the camera uniforms the graph declares', () => {
  const water = new WaterGraph({ ...graph(), resources: { environment: new THREE.CubeTexture() } });
  const camera = new THREE.PerspectiveCamera(55, 16 / 9, 0.1, 200);
  camera.position.set(14, 7, -12);
  camera.lookAt(-4, -1.5, 4);
  water.update(3.5, camera);
  assert.deepEqual(water.uniforms.u_camera_position.value.toArray(), [14, 7, -12]);
  const vp = new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
  assert.deepEqual(water.uniforms.u_view_projection.value.toArray(), vp.toArray());
});

test('time phases are mod(omega t, 2 pi) in double precision, also at large times', () => {
  assert.equal(timePhase(2, 3.5), 7 - 2 * Math.PI);
  const p = timePhase(1.3, 1e7);
  assert.ok(p >= 0 && p < 2 * Math.PI);
  assert.ok(Math.abs(p - ((1.3 * 1e7) % (2 * Math.PI))) < 1e-6);
  assert.equal(timePhase(-1, 1), 2 * Math.PI - 1);
});

test("the default sun is the runtime's default scene sun, a unit vector", () => {
  // runtime/scene.cpp: (cos el cos az, sin el, cos el sin az) at azimuth 110, elevation 30 degrees.
  const sun = sunFromAngles(110, 30);
  const expected = [-0.29619813272602386, 0.5, 0.8137976813493738];
  sun.toArray().forEach((x, i) => assert.ok(Math.abs(x - expected[i]) < 1e-12, `component ${i}: ${x}`));
  assert.ok(Math.abs(sun.length() - 1) < 1e-12);
});

test('the water grid is the runtime one: 40 m across, uv 0..1, (n+1)^2 vertices', () => {
  const g = createWaterGridGeometry(4);
  assert.equal(g.getAttribute('a_position').count, 25);
  assert.equal(g.index.count, 4 * 4 * 6);
  assert.deepEqual(Array.from(g.getAttribute('a_position').array.slice(0, 3)), [-20, 0, -20]);
  assert.deepEqual(Array.from(g.getAttribute('a_position').array.slice(-3)), [20, 0, 20]);
  assert.deepEqual(Array.from(g.getAttribute('a_uv').array.slice(-2)), [1, 1]);
  assert.deepEqual(Array.from(g.index.array.slice(0, 6)), [0, 5, 1, 1, 5, 6]);
});

test('a manifest texture\'s sampler state sets wrap, filters, mipmaps and colour space', () => {
  // No "sampler": the default every node texture had, as the runtime uploads it.
  const plain = applySamplerState(new THREE.Texture());
  assert.equal(plain.wrapS, THREE.RepeatWrapping);
  assert.equal(plain.wrapT, THREE.RepeatWrapping);
  assert.equal(plain.minFilter, THREE.LinearFilter);
  assert.equal(plain.magFilter, THREE.LinearFilter);
  assert.equal(plain.generateMipmaps, false);
  assert.equal(plain.colorSpace, THREE.NoColorSpace);
  const mip = applySamplerState(new THREE.Texture(), { wrap: 'mirror', filter: 'mipmapped', color_space: 'srgb' });
  assert.equal(mip.wrapS, THREE.MirroredRepeatWrapping);
  assert.equal(mip.wrapT, THREE.MirroredRepeatWrapping);
  assert.equal(mip.minFilter, THREE.LinearMipmapLinearFilter);
  assert.equal(mip.magFilter, THREE.LinearFilter);
  assert.equal(mip.generateMipmaps, true);
  assert.equal(mip.colorSpace, THREE.SRGBColorSpace);
  const near = applySamplerState(new THREE.Texture(), { wrap: 'clamp', filter: 'nearest', color_space: 'linear' });
  assert.equal(near.wrapS, THREE.ClampToEdgeWrapping);
  assert.equal(near.minFilter, THREE.NearestFilter);
  assert.equal(near.magFilter, THREE.NearestFilter);
  assert.equal(near.colorSpace, THREE.NoColorSpace);
  assert.throws(() => applySamplerState(new THREE.Texture(), { wrap: 'border', filter: 'linear', color_space: 'srgb' }),
    (e) => e instanceof WaterGraphError && e.message.includes('unknown sampler state'));
});

test("the passes and render targets follow the runtime's planner (runtime/pass_plan.cpp)", () => {
  const all = ['environment_cubemap', 'depth_prepass', 'planar_reflection', 'refraction', 'scene_color_copy',
    'deferred_water', 'water_surface'];
  const plan = planPasses({ graph: 'all', passes: [...all].reverse() }, description(),
    { width: 320, height: 180, environmentSize: 64 });
  // Execution order whatever the manifest's, the opaque scene always.
  // The output transform last, as the runtime always runs it.
  assert.deepEqual(plan.passes, ['environment_cubemap', 'depth_prepass', 'planar_reflection', 'refraction',
    'opaque_scene', 'scene_color_copy', 'deferred_water', 'water_surface', 'output_transform']);
  // Linear radiance in half floats wherever the runtime has RGBA16F; the G-buffer RGBA32F.
  assert.deepEqual(plan.targets.map((t) => [t.name, t.width, t.height, t.color, t.depth]), [
    ['frame', 320, 180, 'rgba16f', true],
    ['environment', 64, 64, 'rgba16f', false],
    ['scene_depth', 320, 180, null, true],
    ['reflection', 320, 180, 'rgba16f', true],
    ['refraction', 320, 180, 'rgba16f', true],
    ['scene_color', 320, 180, 'rgba16f', false],
    ['water_normal', 320, 180, 'rgba32f', false],
    ['water_position', 320, 180, 'rgba32f', true],
    ['display', 320, 180, 'rgba8', false],
  ]);
  // Only what is listed.
  const lake = planPasses({ graph: 'lake', passes: ['water_surface'] }, description(), { width: 8, height: 8, environmentSize: 4 });
  assert.deepEqual(lake.passes, ['opaque_scene', 'water_surface', 'output_transform']);
  assert.deepEqual(lake.targets.map((t) => t.name), ['frame', 'display']);
  // The RGBA8 fallback changes the frame-format targets only.
  const small = planPasses({ graph: 'all', passes: all }, description(), { width: 8, height: 8, environmentSize: 4, frameFormat: 'rgba8' });
  assert.deepEqual(small.targets.map((t) => t.color),
    ['rgba8', 'rgba8', null, 'rgba8', 'rgba8', 'rgba8', 'rgba32f', 'rgba32f', 'rgba8']);
  // The runtime's own passes are never listed by a manifest.
  for (const own of ['opaque_scene', 'output_transform'])
    assert.throws(() => planPasses({ graph: 'x', passes: ['water_surface', own] }, description(),
      { width: 8, height: 8, environmentSize: 4 }), new RegExp(`graph 'x' lists an unknown pass '${own}'`));
  assert.throws(() => planPasses({ graph: 'x', passes: ['water_surface', 'shadow_map'] }, description(),
    { width: 8, height: 8, environmentSize: 4 }), /graph 'x' lists an unknown pass 'shadow_map'/);
  assert.throws(() => planPasses({ graph: 'x', passes: ['depth_prepass'] }, description(),
    { width: 8, height: 8, environmentSize: 4 }), /lacks water_surface/);
});

test('a scaled pass ("pass_scales") gets targets that fraction of the frame, rounded as the runtime', () => {
  const all = ['environment_cubemap', 'depth_prepass', 'scene_color_copy', 'deferred_water', 'water_surface'];
  const plan = planPasses({ graph: 'half', passes: all, pass_scales: { depth_prepass: 0.5, deferred_water: 0.25 } },
    description(), { width: 321, height: 181, environmentSize: 64 });
  assert.deepEqual(plan.targets.map((t) => [t.name, t.width, t.height]), [
    ['frame', 321, 181],
    ['environment', 64, 64],      // the cube map keeps its own size
    ['scene_depth', 161, 91],     // 160.5 -> 161, 90.5 -> 91 (std::lround)
    ['scene_color', 321, 181],    // not scaled
    ['water_normal', 80, 45],
    ['water_position', 80, 45],
    ['display', 321, 181],        // the output transform writes the frame's size
  ]);
  assert.throws(() => planPasses({ graph: 'x', passes: ['water_surface'], pass_scales: { refraction: 0.5 } }, description(),
    { width: 8, height: 8, environmentSize: 4 }), /scales pass 'refraction', which it does not list/);
});

test("the client's resource -> pass table is the runtime's", () => {
  const runtime = Object.fromEntries(description().render_targets.map((t) => [t.resource, t.pass]));
  assert.ok(description().render_passes.includes('output_transform'));
  assert.deepEqual(RESOURCE_PASSES, runtime);
});

test('with a scene description the client renders the passes and binds their textures', () => {
  const water = new WaterGraph({ ...graph(), description: description() });
  assert.deepEqual(water.passes.plan.passes, ['environment_cubemap', 'opaque_scene', 'water_surface', 'output_transform']);
  const env = water.uniforms.u_environment.value;
  assert.ok(env.isCubeTexture && env.isRenderTargetTexture, 'u_environment is the environment pass\'s cube');
  assert.equal(water.passes.targets.environment.target.width, description().environment.size);
  const mesh = water.createMesh();
  assert.ok(mesh.layers.isEnabled(WATER_LAYER) && mesh.layers.isEnabled(0));
  assert.equal(water.deferred, false);
  // A pass a newer runtime describes and this client cannot run: refused by name at once.
  const newer = description();
  newer.render_passes.splice(1, 0, 'shadow_map');
  assert.throws(() => new WaterGraph({ ...graph(), manifest: { ...graph().manifest, passes: ['shadow_map', 'water_surface'] },
    description: newer }), /graph 'three_environment' needs passes this client cannot render: shadow_map/);
});
