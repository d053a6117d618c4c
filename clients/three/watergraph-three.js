// watergraph's es300 output in three.js: a RawShaderMaterial built from a compiled graph's
// shaders and manifest, with the uniforms, textures and grid mesh the runtime
// (runtime/renderer.cpp) gives the same shaders, so both draw the same pixels.
// See README.md beside this file for the API and what is not supported.
import * as THREE from 'three';
import { WaterPasses, WaterGraphError, WATER_LAYER, fullScreenTriangle, checkSceneDescription, runtimeShaderForm, shaderForm } from './watergraph-passes.js';
import { manifestView, renderView } from './watergraph-output.js';
import { checkManifest, has } from './watergraph-manifest.js';
import { OceanSimulation } from './watergraph-ocean.js';

export { WaterGraphError };
export { TONE_MAPPERS, EXPOSURE_RANGE } from './watergraph-output.js';
export { checkManifest } from './watergraph-manifest.js';

// A table keyed by names that come from a manifest: without a prototype, so that
// "__proto__" or "constructor" is no member of it (a parameter named __proto__ set through
// a plain object's prototype setter and was lost).
const table = (entries = {}) => Object.assign(Object.create(null), entries);

const TWO_PI = 6.283185307179586;

// The options WaterGraph.render() takes.
const RENDER_OPTIONS = ['toneMapping', 'exposure', 'outputTransform'];

// mod(omega * t, 2 pi) in double precision, as the runtime computes time_phase uniforms:
// the shader then adds a phase in [0, 2 pi) instead of multiplying a huge time in float.
export function timePhase(angularFrequency, time) {
  const phase = angularFrequency * time;
  return phase - TWO_PI * Math.floor(phase / TWO_PI);
}

// The scene resources a manifest may list and the pass that renders each
// (codegen/manifest.cpp). Given a scene description (`watergraph scene`), WaterPasses
// renders them; without one, an application that renders one itself passes the texture in
// options.resources. `underwater` (deferred water) also changes how the water is drawn (a
// full-screen pass over a G-buffer): only WaterPasses does that.
export const RESOURCE_PASSES = {
  scene_depth: 'depth_prepass',
  scene_color: 'scene_color_copy',
  planar_reflection: 'planar_reflection',
  refraction: 'refraction',
  environment: 'environment_cubemap',
  underwater: 'deferred_water',
};
const NEEDS_PASSES = new Set(['underwater']);

// The water grid of runtime/scene.cpp (buildWaterGrid): quadsPerSide^2 quads over a square
// of 2 * halfSize metres at y = 0, centred on the origin, normal +y, uv (0,0) at
// (-halfSize, -halfSize) and (1,1) at (halfSize, halfSize), the same triangle order.
// Attributes carry the manifest's names (a_position, a_normal, a_uv).
export function createWaterGridGeometry(quadsPerSide = 128, halfSize = 20) {
  const n = Math.max(Math.floor(quadsPerSide), 1);
  const count = (n + 1) * (n + 1);
  const position = new Float32Array(count * 3);
  const normal = new Float32Array(count * 3);
  const uv = new Float32Array(count * 2);
  for (let j = 0, k = 0; j <= n; ++j) {
    for (let i = 0; i <= n; ++i, ++k) {
      // Computed in float32 steps like the C++ (u = i / n, x = -h + 2h * u).
      const u = Math.fround(i / n), v = Math.fround(j / n);
      position[3 * k] = Math.fround(-halfSize + Math.fround(2 * halfSize * u));
      position[3 * k + 2] = Math.fround(-halfSize + Math.fround(2 * halfSize * v));
      normal[3 * k + 1] = 1;
      uv[2 * k] = u;
      uv[2 * k + 1] = v;
    }
  }
  const index = new Uint32Array(n * n * 6);
  for (let j = 0, k = 0; j < n; ++j) {
    for (let i = 0; i < n; ++i) {
      const a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      index.set([a, c, b, b, c, d], k);
      k += 6;
    }
  }
  const g = new THREE.BufferGeometry();
  g.setAttribute('a_position', new THREE.BufferAttribute(position, 3));
  g.setAttribute('a_normal', new THREE.BufferAttribute(normal, 3));
  g.setAttribute('a_uv', new THREE.BufferAttribute(uv, 2));
  g.setIndex(new THREE.BufferAttribute(index, 1));
  // three.js culls by bounding sphere; displacement moves vertices, so make it generous.
  g.boundingSphere = new THREE.Sphere(new THREE.Vector3(), halfSize * 2);
  return g;
}

// Attribute name -> item size the grid provides (codegen/shader_interface.h locations).
const GRID_ATTRIBUTES = table({ a_position: [0, 3], a_normal: [1, 3], a_uv: [2, 2] });

function checkPasses(manifest, resources, hasPasses = false) {
  const passes = manifest.passes;
  if (!Array.isArray(passes) || !passes.includes('water_surface'))
    throw new WaterGraphError(`graph '${manifest.graph}': the manifest has no "passes" list with water_surface`);
  const missing = [];
  // Without a description the client draws the water alone: a pass it does not know would
  // be skipped silently.
  const known = new Set(['water_surface', ...Object.values(RESOURCE_PASSES)]);
  if (!hasPasses)
    for (const pass of passes) {
      if (pass === 'ocean_simulation') missing.push(`${pass} (a spectral ocean: its passes' shaders come with a scene description)`);
      else if (!known.has(pass)) missing.push(`${pass} (a pass this client does not know)`);
    }
  for (const resource of manifest.resources ?? []) {
    const pass = has(RESOURCE_PASSES, resource) ? RESOURCE_PASSES[resource] : undefined;
    if (!pass) missing.push(`${resource} (an unknown scene resource)`);
    else if (hasPasses) continue;
    else if (NEEDS_PASSES.has(resource))
      missing.push(`${pass} (resource ${resource}: deferred water needs the client's passes: give a scene description)`);
    else if (!(has(resources, resource) && resources[resource])) missing.push(`${pass} (resource ${resource}: pass it in options.resources)`);
  }
  if (missing.length)
    throw new WaterGraphError(
      `graph '${manifest.graph}' needs render passes the three.js client does not provide: ${missing.join('; ')}. ` +
        'Without a scene description (`watergraph scene`) the client draws only the water_surface pass.');
}

// A parameter's manifest default as a THREE value of its type (raw numbers: no colour
// management, the runtime uploads the same floats). A colour parameter ("color_space":
// "srgb") holds the sRGB values a colour picker shows and the shader linearises them, so
// its uniform takes them as they are (from a THREE.Color, its sRGB components).
function parameterValue(u) {
  const d = u.default;
  const v = typeof d === 'boolean' ? [d ? 1 : 0] : Array.isArray(d) ? d : [d];
  if (v.some((x) => typeof x !== 'number'))
    throw new WaterGraphError(`parameter uniform ${u.name} has no numeric "default"`);
  const need = table({ float: 1, int: 1, bool: 1, vec2: 2, vec3: 3, vec4: 4, mat3: 9, mat4: 16 })[u.type];
  if (need === undefined) throw new WaterGraphError(`uniform ${u.name} has a type the client does not know: ${u.type}`);
  if (v.length !== need) throw new WaterGraphError(`uniform ${u.name} of type ${u.type} got ${v.length} value(s)`);
  switch (u.type) {
    case 'vec2': return new THREE.Vector2(...v);
    case 'vec3': return new THREE.Vector3(...v);
    case 'vec4': return new THREE.Vector4(...v);
    case 'mat3': return new THREE.Matrix3().fromArray(v);  // column-major, as GL
    case 'mat4': return new THREE.Matrix4().fromArray(v);
    default: return v[0];
  }
}

// A parameter value clamped into the manifest's [min, max] (NaN to min): the generated
// shader drops guards the range makes dead (watergraph's value facts), so a value outside
// it could make the water NaN.
function clampToRange(x, u) {
  const lo = typeof u.min === 'number' ? u.min : -Infinity;
  const hi = typeof u.max === 'number' ? u.max : Infinity;
  if (!(x >= lo)) return Number.isFinite(lo) ? lo : Number.isFinite(hi) ? hi : x;
  return x > hi ? hi : x;
}

const BUILTIN_INITIAL = table({
  model: () => new THREE.Matrix4(),
  view_projection: () => new THREE.Matrix4(),
  view: () => new THREE.Matrix4(),
  projection: () => new THREE.Matrix4(),
  camera_position: () => new THREE.Vector3(),
  time: () => 0,
  time_phase: () => 0,
  viewport_size: () => new THREE.Vector2(1, 1),
  camera_near_far: () => new THREE.Vector2(0.1, 200),
  // The unit vector towards the sun; until setSunDirection, the runtime's default scene sun
  // (azimuth 110 degrees from +x towards +z, elevation 30 degrees).
  sun_direction: () => sunFromAngles(110, 30),
});

// The direction towards a sun at `azimuth` degrees (from +x towards +z) and `elevation`
// degrees above the horizon, as the runtime's scene computes it.
export function sunFromAngles(azimuth, elevation) {
  const az = (azimuth * Math.PI) / 180, el = (elevation * Math.PI) / 180;
  return new THREE.Vector3(Math.cos(el) * Math.cos(az), Math.sin(el), Math.cos(el) * Math.sin(az)).normalize();
}

// The water: a RawShaderMaterial with every uniform of the manifest, and update().
export class WaterGraph {
  // manifest: the parsed <graph>.manifest.json; shaders: {vertex, fragment}, the graph's es300
  // stages as three.js takes them, each {glsl_version, body}: the manifest's
  // "three".vertex.glsl_version and the text of its "body_file" (<graph>.es300.vert.body: the
  // stage after its version line, which three.js writes itself); textures: sampler name -> THREE.Texture for every manifest
  // texture with a "source" (loadWaterGraph loads them); resources: scene resource name ->
  // THREE texture the application renders itself (see RESOURCE_PASSES). description: a
  // scene description (`watergraph scene`): the client then renders every pass the
  // manifest lists itself (WaterPasses), and render() draws a frame. oceanModule: for a
  // manifest with "oceans", the ES module its entries name (<graph>.ocean.js, imported by
  // loadWaterGraph), from which the ocean_simulation pass simulates them.
  constructor({ manifest, shaders, vertexShader, fragmentShader, textures = {}, resources = {}, description = null, oceanModule = null }) {
    if (!manifest || typeof manifest !== 'object') throw new WaterGraphError('no manifest given');
    if (vertexShader !== undefined || fragmentShader !== undefined)
      throw new WaterGraphError('WaterGraph takes the stages as `shaders: {vertex, fragment}`, each {glsl_version, body} from the ' +
        'manifest\'s "three" (each stage\'s "glsl_version" and its "body_file"), not as whole texts (vertexShader, fragmentShader): see README.md');
    checkManifest(manifest);  // its documented shape, before any of it is used
    checkPasses(manifest, resources, description !== null);
    // The graph's preferred view (the manifest's "color"), which render() uses by default.
    this.view = manifestView(manifest);
    if (description) {
      checkSceneDescription(description);
      this.passes = new WaterPasses(manifest, description, { width: 1, height: 1 });
      resources = this.passes.resources;
    }
    // The spectral oceans' simulation (watergraph-ocean.js), run by render() as the first pass.
    this.ocean = manifest.oceans ? new OceanSimulation(manifest, oceanModule, description) : null;
    // How render() reaches a frame's foam: 'replay' (a still frame: its time's foam alone, as
    // the runtime's render) or 'continue' (an animation: from the previous frame's steps).
    this.foamHistory = 'replay';
    this.time = 0;
    this.frameSize = null;  // the frame render() draws (u_viewport_size), set by render()
    this.meshes = [];
    for (const a of manifest.attributes ?? []) {
      const want = GRID_ATTRIBUTES[a.name];
      if (!want || want[0] !== a.location)
        throw new WaterGraphError(`graph '${manifest.graph}' reads attribute ${a.name} at location ${a.location}, which the water grid does not provide`);
    }
    this.manifest = manifest;
    this.uniforms = table();  // uniform name -> { value }, as three.js takes them
    this.phases = [];  // [uniform name, angular frequency]
    this.builtins = table();  // builtin -> uniform name
    for (const u of manifest.uniforms ?? []) {
      if (!u.name || !u.type) throw new WaterGraphError('a manifest uniform lacks "name" or "type"');
      if ('parameter' in u) {
        this.uniforms[u.name] = { value: parameterValue(u) };
        continue;
      }
      const make = BUILTIN_INITIAL[u.builtin];
      if (!make) throw new WaterGraphError(`uniform ${u.name} asks for builtin '${u.builtin}', which the client does not provide`);
      this.uniforms[u.name] = { value: make() };
      if (u.builtin === 'time_phase') this.phases.push([u.name, u.angular_frequency]);
      else this.builtins[u.builtin] = u.name;
    }
    for (const t of manifest.textures ?? []) {
      let texture;
      if ('source' in t) {
        texture = has(textures, t.name) ? textures[t.name] : undefined;
        if (!texture) throw new WaterGraphError(`texture ${t.name} (${t.source}) was not given`);
      } else if ('ocean' in t) {
        texture = this.ocean.map(t.ocean);
      } else if ('resource' in t) {
        // By sampler first: the G-buffer's two samplers share the resource `underwater`.
        texture = (has(resources, t.name) ? resources[t.name] : undefined) ??
          (has(resources, t.resource) ? resources[t.resource] : undefined);  // checkPasses made sure it is there
        if (!texture) throw new WaterGraphError(`texture ${t.name} (resource ${t.resource}) was not given`);
      } else {
        throw new WaterGraphError(`texture ${t.name} has neither a "source" nor a "resource"`);
      }
      if ((t.type === 'samplerCube') !== (texture.isCubeTexture === true))
        throw new WaterGraphError(`texture ${t.name} is a ${t.type}, but the texture given for it is ${texture.isCubeTexture ? '' : 'not '}a cube texture`);
      this.uniforms[t.name] = { value: texture };
    }
    const es300 = manifest.targets?.es300;
    if (!es300) throw new WaterGraphError(`graph '${manifest.graph}' was not compiled for es300 (compile with --target es300)`);
    const vertex = shaderForm(shaders?.vertex, `graph '${manifest.graph}': shaders.vertex`).body;
    const fragment = shaderForm(shaders?.fragment, `graph '${manifest.graph}': shaders.fragment`).body;
    this.deferred = this.passes?.deferred === true;
    if (this.deferred) {
      // As the runtime: the graph's vertex shader writes the G-buffer (the runtime's
      // G-buffer fragment shader behind it), and its fragment shader runs full-screen.
      this.gbufferMaterial = new THREE.RawShaderMaterial({
        name: `watergraph ${manifest.graph} G-buffer`,
        glslVersion: THREE.GLSL3,
        vertexShader: vertex,
        fragmentShader: runtimeShaderForm(description, 'water_gbuffer_fragment').body,
        uniforms: this.uniforms,
        side: THREE.DoubleSide,
        depthFunc: THREE.LessEqualDepth,
      });
      this.gbufferScene = new THREE.Scene();
      this.gbufferScene.add(this.#trackedMesh(createWaterGridGeometry(description.water.grid_quads, description.water.half_size),
        this.gbufferMaterial));
    }
    this.material = new THREE.RawShaderMaterial({
      name: `watergraph ${manifest.graph}`,
      glslVersion: THREE.GLSL3,
      vertexShader: this.deferred ? runtimeShaderForm(description, 'fullscreen_vertex').body : vertex,
      fragmentShader: fragment,
      uniforms: this.uniforms,
      side: THREE.DoubleSide,  // the runtime draws without face culling
      // The runtime blends by the water's alpha (src alpha, 1 - src alpha) into an opaque frame.
      transparent: true,
      blending: THREE.CustomBlending,
      blendEquation: THREE.AddEquation,
      blendSrc: THREE.SrcAlphaFactor,
      blendDst: THREE.OneMinusSrcAlphaFactor,
      blendSrcAlpha: THREE.OneFactor,
      blendDstAlpha: THREE.OneMinusSrcAlphaFactor,
      depthTest: !this.deferred,  // the full-screen pass shades every pixel
      depthWrite: !this.deferred,
      depthFunc: THREE.LessEqualDepth,
    });
    // The description's sun, which its sky and scene are lit by.
    if (description && this.builtins.sun_direction)
      this.uniforms[this.builtins.sun_direction].value.fromArray(description.sun_direction);
  }

  // A mesh whose world matrix becomes u_model and the drawn frame's size u_viewport_size:
  // with a scene description the frame render() draws (as the runtime, whose every pass reads
  // the frame's size, a scaled one too), else the bound render target's or the drawing
  // buffer's size. The filtered ocean reader measures a pixel's footprint from it.
  #trackedMesh(geometry, material) {
    const mesh = new THREE.Mesh(geometry, material);
    mesh.frustumCulled = false;  // displaced waves may leave the flat grid's bounds
    const size = new THREE.Vector2();
    mesh.onBeforeRender = (renderer) => {
      this.setModelMatrix(mesh.matrixWorld);
      const target = renderer.getRenderTarget();
      if (this.frameSize) size.copy(this.frameSize);
      else if (target) size.set(target.width, target.height);
      else renderer.getDrawingBufferSize(size);
      this.setViewportSize(size.x, size.y);
      // three.js skips the upload when the previous draw used the same material: several
      // meshes sharing it would all get the first one's u_model.
      material.uniformsNeedUpdate = true;
    };
    return mesh;
  }

  // A mesh of the water grid (or `geometry`) with this material. Its world matrix becomes
  // u_model and the renderer's drawing-buffer size u_viewport_size at every draw.
  // With deferred water the mesh is a full-screen triangle (the G-buffer has its own grid,
  // resized by setGridQuads). The mesh is also on WATER_LAYER, which render() draws last.
  createMesh(geometry = createWaterGridGeometry()) {
    const mesh = this.#trackedMesh(this.deferred ? fullScreenTriangle() : geometry, this.material);
    mesh.layers.enable(WATER_LAYER);
    this.meshes.push(mesh);
    return mesh;
  }

  // Deferred water: the G-buffer's grid with `quads` per side (the runtime's --grid).
  setGridQuads(quads) {
    if (!this.deferred) return;
    const mesh = this.gbufferScene.children[0], old = mesh.geometry;
    mesh.geometry = createWaterGridGeometry(quads, this.passes.description.water.half_size);
    old.dispose();
  }

  // One frame into `output` (a render target; null: the canvas): with a scene description,
  // every pass the manifest lists around `scene` (which holds the water mesh), as the
  // runtime runs them, into the linear frame, then the output transform into `output`;
  // without one, plainly renderer.render(scene, camera) (the water's linear values, no
  // output transform). Call update() first. options:
  //   toneMapping  'none', 'aces', 'agx' or 'neutral' (default: the manifest's view)
  //   exposure     EV in [-20, 20] (default: the manifest's view)
  //   outputTransform  false: stop at the linear frame (this.frameTarget), drawing nothing
  //                to the canvas, for a host that does its own output
  render(renderer, scene, camera, output = null, options = {}) {
    for (const key of Object.keys(options ?? {}))
      if (!RENDER_OPTIONS.includes(key))
        throw new WaterGraphError(`unknown render option '${key}' (the options are ${RENDER_OPTIONS.join(', ')})`);
    const outputTransform = options?.outputTransform ?? true;
    if (typeof outputTransform !== 'boolean')
      throw new WaterGraphError(`the render option outputTransform must be true or false (got ${JSON.stringify(outputTransform)})`);
    const linear = !outputTransform;
    const view = linear ? null : renderView(this.view, options ?? {});
    this.frameSize = null;
    if (!this.passes) {
      if (Object.keys(options ?? {}).length)
        throw new WaterGraphError('render options need the output transform, which comes with a scene description (`watergraph scene`)');
      renderer.setRenderTarget(output);
      renderer.render(scene, camera);
      return;
    }
    if (linear && output)
      throw new WaterGraphError('with outputTransform: false nothing is drawn to `output`: read the linear frame from water.frameTarget');
    const size = output ? new THREE.Vector2(output.width, output.height) : renderer.getDrawingBufferSize(new THREE.Vector2());
    this.frameSize = size;
    const remade = this.passes.configure(renderer);
    if (this.passes.setSize(size.x, size.y) || remade) {
      for (const t of this.manifest.textures ?? [])
        if ('resource' in t) this.uniforms[t.name].value = this.passes.resources[t.name] ?? this.passes.resources[t.resource];
    }
    this.passes.render(renderer, scene, camera, this, output, view);
  }

  // With a scene description: the render target holding the last frame's linear radiance
  // (RGBA16F, or RGBA8 where frameFallback says why), its depth in .depthTexture.
  get frameTarget() { return this.passes?.frame ?? null; }
  // 'rgba16f', or 'rgba8' once a render() found the context cannot render half floats
  // (the fallback); null without a scene description.
  get frameFormat() { return this.passes?.frameFormat ?? null; }
  // Why the frame is not RGBA16F (also said once with console.warn), or null.
  get frameFallback() { return this.passes?.frameFallback ?? null; }

  // Sets every time and camera uniform the graph declares. `time` in seconds; `camera` a
  // THREE.PerspectiveCamera (or any camera with near/far) whose matrices are current.
  update(time, camera) {
    const set = (builtin, fn) => {
      const name = this.builtins[builtin];
      if (name) fn(this.uniforms[name]);
    };
    camera.updateMatrixWorld();
    this.time = time;  // the ocean simulation's, in double
    set('time', (u) => { u.value = time; });
    for (const [name, omega] of this.phases) this.uniforms[name].value = timePhase(omega, time);
    set('view', (u) => u.value.copy(camera.matrixWorldInverse));
    set('projection', (u) => u.value.copy(camera.projectionMatrix));
    set('view_projection', (u) => u.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse));
    set('camera_position', (u) => u.value.setFromMatrixPosition(camera.matrixWorld));
    // Each plane clamped into [1e-6, 1e30] (an infinite far plane to 1e30), as the runtime
    // does: the generated depth linearisation relies on that range.
    const plane = (x) => (!(x >= 1e-6) ? 1e-6 : Math.min(x, 1e30));
    set('camera_near_far', (u) => u.value.set(plane(camera.near), plane(camera.far)));
  }

  setModelMatrix(matrix) {
    const name = this.builtins.model;
    if (name) this.uniforms[name].value.copy(matrix);
  }

  // Sets the sun the graph's sun_direction builtin reads (normalised here; a zero vector is refused).
  setSunDirection(direction) {
    if (!(direction.lengthSq() > 0)) throw new WaterGraphError('the sun direction must not be a zero vector');
    const unit = direction.clone().normalize();
    const name = this.builtins.sun_direction;
    if (name) this.uniforms[name].value.copy(unit);
  }

  setViewportSize(width, height) {
    const name = this.builtins.viewport_size;
    if (name) this.uniforms[name].value.set(width, height);
  }

  // Sets a graph parameter by its name in the graph ("deep"), not the uniform's ("p_deep").
  setParameter(parameter, value) {
    const u = (this.manifest.uniforms ?? []).find((x) => x.parameter === parameter);
    if (!u) throw new WaterGraphError(`graph '${this.manifest.graph}' has no parameter '${parameter}' (or it was folded away)`);
    const slot = this.uniforms[u.name];
    if (typeof slot.value === 'number') slot.value = clampToRange(Number(value), u);
    else {
      if (Array.isArray(value)) slot.value.fromArray(value);
      else slot.value.copy(value);
      // Per component, as the runtime does: the shader may rely on the manifest's range.
      const v = slot.value.toArray().map((x) => clampToRange(x, u));
      slot.value.fromArray(v);
    }
  }

  dispose() {
    this.material.dispose();
    this.gbufferMaterial?.dispose();
    this.passes?.dispose();
    this.ocean?.dispose();
    for (const t of this.manifest.textures ?? [])
      if ('source' in t) this.uniforms[t.name]?.value?.dispose();
  }
}

async function fetchOk(url, what) {
  let response;
  try {
    response = await fetch(url);
  } catch (e) {
    throw new WaterGraphError(`cannot load ${what} from ${url}: ${e.message}`);
  }
  if (!response.ok) throw new WaterGraphError(`cannot load ${what} from ${url}: HTTP ${response.status}`);
  return response;
}

// The sampler state of a manifest texture, as the runtime sets it (runtime/node_texture.h):
// its "sampler" entry, or without one the default every node texture had before
// texture_sample (repeat, linear, linear data).
const DEFAULT_SAMPLER = { wrap: 'repeat', filter: 'linear', color_space: 'linear' };
const WRAPS = table({
  repeat: THREE.RepeatWrapping,
  clamp: THREE.ClampToEdgeWrapping,
  mirror: THREE.MirroredRepeatWrapping,
});
const FILTERS = table({  // [minFilter, magFilter, generateMipmaps]
  nearest: [THREE.NearestFilter, THREE.NearestFilter, false],
  linear: [THREE.LinearFilter, THREE.LinearFilter, false],
  mipmapped: [THREE.LinearMipmapLinearFilter, THREE.LinearFilter, true],
});
const COLOR_SPACES = table({ linear: THREE.NoColorSpace, srgb: THREE.SRGBColorSpace });

// Sets `texture`'s wrap, filters, mipmaps and colour space from `sampler` (a manifest
// texture's "sampler", or undefined for the default). sRGB: three.js uploads SRGB8_ALPHA8,
// so WebGL decodes each texel before filtering, as GL does in the runtime; mipmapped:
// gl.generateMipmap, as glGenerateMipmap there.
export function applySamplerState(texture, sampler = undefined) {
  const s = { ...DEFAULT_SAMPLER, ...(sampler ?? {}) };
  const wrap = WRAPS[s.wrap], filter = FILTERS[s.filter], colorSpace = COLOR_SPACES[s.color_space];
  if (wrap === undefined || filter === undefined || colorSpace === undefined)
    throw new WaterGraphError(`unknown sampler state ${JSON.stringify(sampler)} (wrap: repeat, clamp or mirror; ` +
      'filter: nearest, linear or mipmapped; color_space: linear or srgb)');
  texture.wrapS = texture.wrapT = wrap;
  [texture.minFilter, texture.magFilter, texture.generateMipmaps] = filter;
  texture.colorSpace = colorSpace;
  texture.needsUpdate = true;
  return texture;
}

// A node texture written by `watergraph compile --textures` as <graph>.<sampler>.png, with
// the sampling the runtime sets up: RGBA8 as stored (no premultiplication, no colour-space
// conversion of the bytes), the bottom row at v = 0, and the manifest entry's sampler
// state (applySamplerState; the default without one).
export async function loadNodeTexture(url, what = url, sampler = undefined) {
  const blob = await (await fetchOk(url, what)).blob();
  const bitmap = await createImageBitmap(blob, {
    imageOrientation: 'flipY',
    premultiplyAlpha: 'none',
    colorSpaceConversion: 'none',
  });
  const t = new THREE.Texture(bitmap);
  t.flipY = false;  // WebGL ignores it for ImageBitmap; the bitmap is already flipped
  t.premultiplyAlpha = false;
  return applySamplerState(t, sampler);
}

// Loads <graph>.manifest.json from `manifestUrl`, the es300 stages' bodies and the node textures
// beside it (compile with `--target es300 --textures`), and builds the WaterGraph.
// options.resources: scene resource textures the application renders (see README.md).
export async function loadWaterGraph(manifestUrl, { resources = {}, description = null } = {}) {
  const base = new URL(manifestUrl, globalThis.location?.href);
  const manifest = await (await fetchOk(base, 'the manifest')).json();
  checkManifest(manifest);
  checkPasses(manifest, resources, description !== null);  // before fetching anything else
  const es300 = manifest.targets?.es300;
  if (!es300?.vert || !es300?.frag)
    throw new WaterGraphError(`graph '${manifest.graph}' was not compiled for es300 (compile with --target es300)`);
  const three = manifest.three;
  if (!three)
    throw new WaterGraphError(`graph '${manifest.graph}': the manifest has no "three" (the es300 stages' bodies): compile it again with this watergraph`);
  // The stages after their version line, which three.js writes itself (checkManifest: plain
  // file names beside the manifest), with the version they lack.
  const form = async (stage) => ({ glsl_version: three[stage].glsl_version,
    body: await (await fetchOk(new URL(three[stage].body_file, base), three[stage].body_file)).text() });
  const [vertex, fragment] = await Promise.all([form('vertex'), form('fragment')]);
  const shaders = { vertex, fragment };
  // The oceans' module (checkManifest: a .js file name beside the manifest), as an ES module.
  const oceanModule = manifest.oceans ? await importOceanModule(new URL(manifest.oceans[0].module, base)) : null;
  const textures = table();
  for (const t of manifest.textures ?? []) {
    if (!('source' in t)) continue;
    const file = t.file;  // named by the manifest, beside it (checkManifest: a plain file name)
    textures[t.name] = await loadNodeTexture(
      new URL(file, base),
      `texture ${t.name} (${t.source}) as ${file}, written by \`watergraph compile --textures\``, t.sampler);
  }
  return new WaterGraph({ manifest, shaders, textures, resources, description, oceanModule });
}

async function importOceanModule(url) {
  try {
    return await import(url.href);
  } catch (e) {
    throw new WaterGraphError(`cannot load the ocean module from ${url} (written by \`watergraph compile --target es300\`): ${e.message}`);
  }
}
