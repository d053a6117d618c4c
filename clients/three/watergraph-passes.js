// The render passes a watergraph manifest asks for, in three.js terms, around the
// application's own scene: the same passes, render targets, clip planes and order as the
// runtime (runtime/pass_plan.cpp, runtime/renderer.cpp), so the same shaders read the same
// textures. The runtime's planner tables and its own shaders (sky, full-screen triangle,
// water G-buffer) come from the scene description `watergraph scene` writes.
import * as THREE from 'three';
import { OutputTransform, checkColorDescription } from './watergraph-output.js';
import { WaterGraphError } from './watergraph-error.js';

// Thrown for a manifest or description the client cannot run (a pass it cannot provide, an
// unknown builtin uniform or type) and for files that cannot be loaded; watergraph-three.js
// exports it too.
export { WaterGraphError };

// The passes render() knows how to run.
const CLIENT_PASSES = new Set(['ocean_simulation', 'environment_cubemap', 'depth_prepass', 'planar_reflection', 'refraction', 'opaque_scene',
  'scene_color_copy', 'deferred_water', 'water_surface', 'output_transform']);
// The passes the runtime always runs, which a manifest never lists.
const RUNTIME_PASSES = new Set(['opaque_scene', 'output_transform']);

// The layer the water's own meshes live on: scene passes leave it out, the water pass
// draws only it.
export const WATER_LAYER = 31;

const SCENE_FORMAT = 'watergraph-scene-2';

// Checks the parts of a scene description (`watergraph scene`) the passes use.
export function checkSceneDescription(description) {
  if (!description || description.format !== SCENE_FORMAT)
    throw new WaterGraphError(`not a scene description of format ${SCENE_FORMAT} (write one with \`watergraph scene -o scene.json\`)`);
  for (const key of ['render_passes', 'render_targets', 'shaders', 'three', 'environment', 'sun_direction', 'clear_color', 'color'])
    if (!(key in description))
      throw new WaterGraphError(`the scene description has no "${key}" (write it again with this watergraph: \`watergraph scene -o scene.json\`)`);
  checkColorDescription(description);
  return description;
}

// A frame dimension times a pass's scale (the manifest's "pass_scales"; absent: 1),
// rounded half away from zero as runtime/pass_plan.cpp's scaledSize, at least 1.
export function scaledSize(size, scale) {
  return Math.max(1, Math.round(size * scale));
}

// Which passes run and which render targets exist, as runtime/pass_plan.cpp decides them:
// a pass runs only when the manifest lists it (the opaque scene always); each pass gets a
// target per scene sampler of the resources it produces, frame-sized or the fraction of
// the frame the manifest's "pass_scales" gives the pass (cube faces environmentSize
// square), "frame" first; the output transform last, into the displayed image ("display",
// the canvas or the caller's target here). frameFormat: the colour of the frame and of every
// target of the description's "frame" format, "rgba16f" as the runtime's (linear radiance),
// "rgba8" where the context cannot render half floats.
export function planPasses(manifest, description, { width, height, environmentSize, frameFormat = 'rgba16f' }) {
  const listed = new Set(manifest.passes ?? []);
  if (!listed.has('water_surface')) throw new WaterGraphError(`graph '${manifest.graph}': the manifest's "passes" list lacks water_surface`);
  if (!(width > 0 && height > 0 && environmentSize > 0)) throw new WaterGraphError('render size must be positive');
  for (const pass of listed)
    if (!description.render_passes.includes(pass) || RUNTIME_PASSES.has(pass))
      throw new WaterGraphError(`graph '${manifest.graph}' lists an unknown pass '${pass}'`);
  const frameColor = frameFormat;
  const plan = { passes: [], targets: [{ name: 'frame', pass: 'water_surface', sampler: '', color: frameColor, depth: true, width, height, cube: false }] };
  const scales = manifest.pass_scales ?? {};
  for (const pass of Object.keys(scales))
    if (!listed.has(pass)) throw new WaterGraphError(`graph '${manifest.graph}' scales pass '${pass}', which it does not list`);
  for (const pass of description.render_passes) {
    if (pass === 'output_transform') {
      plan.passes.push(pass);
      plan.targets.push({ name: 'display', pass, sampler: '', color: 'rgba8', depth: false, width, height, cube: false });
      continue;
    }
    if (pass !== 'opaque_scene' && !listed.has(pass)) continue;
    plan.passes.push(pass);
    const scale = Object.prototype.hasOwnProperty.call(scales, pass) ? scales[pass] : 1;
    for (const t of description.render_targets) {
      if (t.pass !== pass) continue;
      plan.targets.push({
        name: t.target, pass, sampler: t.sampler, resource: t.resource,
        color: targetColor(t, frameColor),
        depth: t.depth, cube: t.cube,
        width: t.cube ? environmentSize : scaledSize(width, scale),
        height: t.cube ? environmentSize : scaledSize(height, scale),
      });
    }
  }
  return plan;
}

function targetColor(t, frameColor) {
  switch (t.color) {
    case 'none': return null;
    case 'float32': return 'rgba32f';
    case 'frame': return frameColor;
    default: throw new WaterGraphError(`the scene description's target ${t.target} has an unknown colour format '${t.color}'`);
  }
}

// Whether a WebGL 2 context can render into RGBA16F: with EXT_color_buffer_float (which
// three.js enables when the context offers it) or EXT_color_buffer_half_float.
export function rendersHalfFloat(renderer) {
  return renderer.extensions.has('EXT_color_buffer_float') || renderer.extensions.has('EXT_color_buffer_half_float');
}

// glm::perspective: the runtime's projection (three's makePerspective rounds differently).
export function glPerspective(fovYDegrees, aspect, near, far, target = new THREE.Matrix4()) {
  const f = 1 / Math.tan((fovYDegrees * Math.PI) / 360);
  return target.set(
    f / aspect, 0, 0, 0,
    0, f, 0, 0,
    0, 0, -(far + near) / (far - near), -(2 * far * near) / (far - near),
    0, 0, -1, 0);
}

// A shader as three.js's RawShaderMaterial takes it: its body (the text after its version
// line) and the version apart, which three.js writes as the first line (glslVersion) with
// its own #defines after it. watergraph writes both parts: `watergraph scene` the runtime's
// shaders (the description's "three".shaders), `compile --target es300` the graph's stages
// (the manifest's "three": each stage's "body_file" and "glsl_version"). Returns `form`, or
// throws naming `what`.
export function shaderForm(form, what) {
  if (!form || typeof form !== 'object' || typeof form.body !== 'string' || typeof form.glsl_version !== 'string')
    throw new WaterGraphError(`${what} has no form for three.js (a "glsl_version" and a "body")`);
  if (form.glsl_version !== THREE.GLSL3)
    throw new WaterGraphError(`${what} is GLSL ${form.glsl_version}; this client draws GLSL ${THREE.GLSL3} (THREE.GLSL3)`);
  return form;
}

// The form of the description's runtime shader `name`.
export function runtimeShaderForm(description, name) {
  return shaderForm(description.three?.shaders?.[name], `the scene description's shader '${name}' ("three".shaders)`);
}

// A RawShaderMaterial of one of the runtime's own ES 3.00 shaders.
export function runtimeMaterial(description, vertex, fragment, uniforms, extra = {}) {
  const v = runtimeShaderForm(description, vertex), f = runtimeShaderForm(description, fragment);
  return new THREE.RawShaderMaterial({
    name: `watergraph runtime ${vertex} + ${fragment}`,
    glslVersion: v.glsl_version,
    vertexShader: v.body,
    fragmentShader: f.body,
    uniforms,
    side: THREE.DoubleSide,  // the runtime draws without face culling
    depthFunc: THREE.LessEqualDepth,
    ...extra,
  });
}

// Three vertices the shader never reads (the runtime's full-screen triangles use
// gl_VertexID); three.js draws as many vertices as "position" holds.
export function fullScreenTriangle() {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(9), 3));
  return g;
}

// The runtime's clip-plane convention for its own shaders: the first of the renderer's
// clipping planes (world space, kept side positive) in the object's space, or "no clip".
const NO_CLIP = new THREE.Vector4(0, 0, 0, 1);
export function objectClipPlane(renderer, object, target) {
  const p = renderer.clippingPlanes?.[0];
  if (!p) return target.copy(NO_CLIP);
  // dot(plane, M p) = dot(M^T plane, p)
  const e = object.matrixWorld.elements, n = p.normal, w = p.constant;
  return target.set(
    e[0] * n.x + e[1] * n.y + e[2] * n.z + e[3] * w,
    e[4] * n.x + e[5] * n.y + e[6] * n.z + e[7] * w,
    e[8] * n.x + e[9] * n.y + e[10] * n.z + e[11] * w,
    e[12] * n.x + e[13] * n.y + e[14] * n.z + e[15] * w);
}

// The runtime's sky (a full-screen triangle at the far plane, drawn after the opaque scene
// without depth writes) as a mesh: its inverse view-projection follows the camera and the
// sky object's world matrix (mirrored in the reflection pass, as the runtime's sky is).
export function createSky(description, sunDirection = new THREE.Vector3().fromArray(description.sun_direction)) {
  const uniforms = { u_inverse_view_projection: { value: new THREE.Matrix4() }, u_sun_direction: { value: sunDirection } };
  const material = runtimeMaterial(description, 'sky_vertex', 'sky_fragment', uniforms, { depthWrite: false });
  const sky = new THREE.Mesh(fullScreenTriangle(), material);
  sky.name = 'watergraph sky';
  sky.frustumCulled = false;
  sky.renderOrder = Number.MAX_SAFE_INTEGER;  // after every opaque object
  sky.onBeforeRender = (renderer, scene, camera) => {
    uniforms.u_inverse_view_projection.value.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse)
      .multiply(sky.matrixWorld).invert();
    material.uniformsNeedUpdate = true;
  };
  return sky;
}

// The passes of one graph at one size: creates the render targets of the plan and renders
// them from the application's scene and camera. `resources` holds, for WaterGraph, the
// texture of each scene resource (and, for deferred water, of each G-buffer sampler).
export class WaterPasses {
  constructor(manifest, description, { width, height, environmentSize = description.environment.size, environment = null }) {
    this.manifest = manifest;
    this.description = checkSceneDescription(description);
    this.environmentSize = environmentSize;
    // What the environment cube sees: the runtime draws only its sky there.
    this.environmentScene = environment ?? new THREE.Scene().add(createSky(description));
    this.resources = Object.create(null);  // keyed by names from the manifest and description
    // Until render() has seen the renderer, the runtime's format; frameFallback says why the
    // frame is not RGBA16F once it is not.
    this.frameFormat = 'rgba16f';
    this.frameFallback = null;
    this.checkedRenderer = null;
    this.output = new OutputTransform(description);
    this.#createTargets(width, height);
    // A pass the runtime has and this client does not (a newer description) is refused now,
    // not at the first frame.
    const unknown = this.plan.passes.filter((p) => !CLIENT_PASSES.has(p));
    if (unknown.length) throw new WaterGraphError(`graph '${manifest.graph}' needs passes this client cannot render: ${unknown.join(', ')}`);
    this.deferred = this.plan.passes.includes('deferred_water');
    this.sceneColorCopy = this.plan.passes.includes('scene_color_copy');
  }

  // Frame-sized targets follow the drawing buffer: called by render() when it changes.
  // Returns whether the targets were made anew (their textures must be bound again).
  setSize(width, height) {
    if (width === this.width && height === this.height) return false;
    this.#disposeTargets();
    this.#createTargets(width, height);
    return true;
  }

  // The frame's format for `renderer`'s context: RGBA16F where it can render half floats,
  // else RGBA8, said once (console.warn and frameFallback), never silently. Returns whether
  // the targets were made anew.
  configure(renderer) {
    if (this.checkedRenderer === renderer) return false;
    this.checkedRenderer = renderer;
    if (this.deferred && !renderer.extensions.has('EXT_color_buffer_float'))
      throw new WaterGraphError(`graph '${this.manifest.graph}' uses deferred water, whose G-buffer is RGBA32F: ` +
        'this WebGL 2 context has no EXT_color_buffer_float to render it');
    if (this.manifest.oceans && !renderer.extensions.has('EXT_color_buffer_float'))
      throw new WaterGraphError(`graph '${this.manifest.graph}' has a spectral ocean, whose simulation renders into RGBA32F and R32F ` +
        'textures: this WebGL 2 context has no EXT_color_buffer_float to render it');
    const format = rendersHalfFloat(renderer) ? 'rgba16f' : 'rgba8';
    if (format === this.frameFormat) return false;
    this.frameFormat = format;
    if (format === 'rgba8') {
      this.frameFallback = 'this WebGL 2 context has neither EXT_color_buffer_float nor EXT_color_buffer_half_float, ' +
        'so the frame and the scene targets are RGBA8: radiance above 1 is clipped before the output transform and ' +
        'dark tones are banded';
      console.warn(`watergraph: ${this.frameFallback}`);
    } else {
      this.frameFallback = null;
    }
    this.#disposeTargets();
    this.#createTargets(this.width, this.height);
    return true;
  }

  #createTargets(width, height) {
    this.width = width;
    this.height = height;
    this.plan = planPasses(this.manifest, this.description,
      { width, height, environmentSize: this.environmentSize, frameFormat: this.frameFormat });
    this.targets = Object.create(null);
    // Linear filtering (half floats filter in every WebGL 2 context), and the type of the
    // frame's colour: linear radiance in half floats, as the runtime's RGBA16F.
    const linear = { minFilter: THREE.LinearFilter, magFilter: THREE.LinearFilter, generateMipmaps: false,
      type: this.frameFormat === 'rgba16f' ? THREE.HalfFloatType : THREE.UnsignedByteType };
    // The frame, as the runtime's: RGBA16F colour and a DEPTH_COMPONENT32F depth buffer the
    // water is depth-tested against; the output transform reads it at the end.
    this.frame = new THREE.WebGLRenderTarget(width, height, { ...linear, depthBuffer: true });
    this.frame.depthTexture = new THREE.DepthTexture(width, height, THREE.FloatType);
    for (const t of this.plan.targets) {
      if (t.name === 'frame' || t.name === 'display' || this.targets[t.name] || t.resource === 'underwater') continue;
      let target, texture;
      if (t.cube) {
        target = new THREE.WebGLCubeRenderTarget(t.width, { ...linear, depthBuffer: false });
        texture = target.texture;
      } else if (t.pass === 'scene_color_copy') {
        // The frame's colour blitted in (the runtime's glBlitFramebuffer): texel for texel
        // at the frame's size, filtered (GL_LINEAR) where "pass_scales" makes it smaller.
        target = new THREE.WebGLRenderTarget(t.width, t.height, { ...linear, depthBuffer: false });
        texture = target.texture;
      } else if (!t.color) {
        // Depth only (the depth pre-pass): DEPTH_COMPONENT32F, nearest; three.js needs a
        // colour attachment beside it, which nothing reads.
        target = new THREE.WebGLRenderTarget(t.width, t.height, { ...linear, type: THREE.UnsignedByteType, depthBuffer: true });
        target.depthTexture = new THREE.DepthTexture(t.width, t.height, THREE.FloatType);
        texture = target.depthTexture;
      } else {
        target = new THREE.WebGLRenderTarget(t.width, t.height, { ...linear, depthBuffer: t.depth });
        texture = target.texture;
      }
      this.targets[t.name] = { spec: t, target, texture };
      this.resources[t.resource] = texture;
    }
    if (this.plan.passes.includes('deferred_water')) {
      // The water G-buffer: two RGBA32F attachments read texel for texel (nearest), in the
      // order of the description's targets (water_normal, water_position), and depth.
      const g = this.plan.targets.filter((t) => t.resource === 'underwater');
      const target = new THREE.WebGLRenderTarget(g[0].width, g[0].height, {
        count: g.length, type: THREE.FloatType, format: THREE.RGBAFormat, depthBuffer: true,
        minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false,
      });
      // Attachment 0 is water_position (the G-buffer shader's o_surface), 1 water_normal.
      const order = ['water_position', 'water_normal'];
      g.forEach((t) => { this.resources[t.sampler] = target.textures[order.indexOf(t.name)]; });
      this.gbuffer = target;
    }
  }

  #disposeTargets() {
    this.frame.dispose();
    for (const { target, texture } of Object.values(this.targets)) (target ?? texture).dispose();
    this.gbuffer?.dispose();
    this.gbuffer = undefined;
  }

  dispose() {
    this.#disposeTargets();
    this.output.dispose();
  }

  // Renders every planned pass of one frame into the frame target: the application's
  // `scene` (built-in scene included, if it added one) seen by `camera`, and the water
  // objects of `water` (on WATER_LAYER); then, unless `view` is null, the output transform
  // through `view` ({toneMapping, exposure}) into `output` (null: the canvas). With `view`
  // null the linear frame stays in this.frame for the caller. water.update() must have run.
  render(renderer, scene, camera, water, output = null, view = null) {
    const saved = {
      autoClear: renderer.autoClear, clipping: renderer.clippingPlanes, mask: camera.layers.mask,
      target: renderer.getRenderTarget(), clear: renderer.getClearColor(new THREE.Color()), alpha: renderer.getClearAlpha(),
      background: scene.background,
    };
    const [r, g, b, a] = this.description.clear_color;
    renderer.setClearColor(new THREE.Color(r, g, b), a);
    renderer.autoClear = true;
    // The water is drawn by the water pass only (it may sit in `scene` on layer 0 too).
    const waterVisible = water.meshes.map((m) => m.visible);
    water.meshes.forEach((m) => { m.visible = false; });
    const side = camera.getWorldPosition(new THREE.Vector3()).y >= 0 ? 1 : -1;  // the camera's side of the water
    const frame = this.frame;
    try {
      for (const pass of this.plan.passes) {
        switch (pass) {
          // Every ocean's maps at the water's time (watergraph-ocean.js); they hold it after.
          case 'ocean_simulation': water.ocean.update(renderer, water.time, water.foamHistory); break;
          case 'environment_cubemap': this.#environment(renderer); break;
          case 'depth_prepass': this.#sceneInto(renderer, scene, camera, this.targets.scene_depth.target, null, false); break;
          // Reflected: what is on the camera's side of the water; refracted: the other side.
          case 'planar_reflection': this.#sceneInto(renderer, scene, camera, this.targets.reflection.target, new THREE.Plane(new THREE.Vector3(0, side, 0), 0), true); break;
          case 'refraction': this.#sceneInto(renderer, scene, camera, this.targets.refraction.target, new THREE.Plane(new THREE.Vector3(0, -side, 0), 0), false); break;
          case 'opaque_scene': this.#sceneInto(renderer, scene, camera, frame, null, false); break;
          case 'scene_color_copy': this.#blit(renderer, frame, this.targets.scene_color.target); break;
          case 'deferred_water': this.#gbuffer(renderer, camera, water); break;
          case 'water_surface': {
            renderer.setRenderTarget(frame);
            renderer.autoClear = false;
            scene.background = null;
            water.meshes.forEach((m, i) => { m.visible = waterVisible[i]; });
            camera.layers.set(WATER_LAYER);
            renderer.render(scene, camera);
            camera.layers.mask = saved.mask;
            renderer.autoClear = true;
            break;
          }
          case 'output_transform':
            if (view) this.output.render(renderer, frame, output, view);
            break;
          default: throw new WaterGraphError(`the client has no pass '${pass}'`);
        }
      }
    } finally {
      renderer.clippingPlanes = saved.clipping;
      renderer.autoClear = saved.autoClear;
      renderer.setClearColor(saved.clear, saved.alpha);
      renderer.setRenderTarget(saved.target);
      camera.layers.mask = saved.mask;
      scene.background = saved.background;
      water.meshes.forEach((m, i) => { m.visible = waterVisible[i]; });
    }
  }

  // The scene (not the water) into `target`, keeping the side of `clip` (world space, before
  // any mirroring) when given. mirror: seen in the water plane y = 0, as the runtime's
  // mirrored camera sees it; done by mirroring the scene, so three.js also turns the winding
  // of every object around (the runtime draws without culling; three.js culls by material).
  #sceneInto(renderer, scene, camera, target, clip, mirror) {
    renderer.setRenderTarget(target);
    renderer.clippingPlanes = clip ? [clip] : [];
    if (mirror) {
      // Clipping planes apply in world space, after the mirror: the kept side flips.
      renderer.clippingPlanes = [new THREE.Plane(new THREE.Vector3(clip.normal.x, -clip.normal.y, clip.normal.z), clip.constant)];
      scene.scale.y = -scene.scale.y;
      scene.updateMatrixWorld(true);
    }
    try {
      renderer.render(scene, camera);
    } finally {
      if (mirror) {
        scene.scale.y = -scene.scale.y;
        scene.updateMatrixWorld(true);
      }
      renderer.clippingPlanes = [];
    }
  }

  // The colour of `source` into `target`, as the runtime's scene colour copy: texel for
  // texel at the same size, filtered where the target is smaller (a reduced scene
  // resolution).
  #blit(renderer, source, target) {
    renderer.setRenderTarget(target);  // three.js makes its framebuffer, bound for drawing
    const gl = renderer.getContext();
    const same = source.width === target.width && source.height === target.height;
    // Raw binds: three.js tracks no read framebuffer here, and binding null restores its view.
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, renderer.properties.get(source).__webglFramebuffer);
    gl.blitFramebuffer(0, 0, source.width, source.height, 0, 0, target.width, target.height, gl.COLOR_BUFFER_BIT,
      same ? gl.NEAREST : gl.LINEAR);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
  }

  // The sky into the six faces of the environment cube, with the runtime's views.
  #environment(renderer) {
    const env = this.description.environment, cube = this.targets.environment.target;
    const camera = new THREE.PerspectiveCamera(env.fov_y_degrees, 1, env.near, env.far);
    glPerspective(env.fov_y_degrees, 1, env.near, env.far, camera.projectionMatrix);
    camera.projectionMatrixInverse.copy(camera.projectionMatrix).invert();
    camera.matrixAutoUpdate = false;
    camera.matrixWorldAutoUpdate = false;
    env.faces.forEach((face, f) => {
      const view = new THREE.Matrix4().lookAt(new THREE.Vector3(), new THREE.Vector3().fromArray(face.direction),
        new THREE.Vector3().fromArray(face.up));  // a camera at the origin looking along direction
      camera.matrixWorld.copy(view);
      camera.matrixWorldInverse.copy(view).invert();
      renderer.setRenderTarget(cube, f);
      renderer.render(this.environmentScene, camera);
    });
  }

  // The water G-buffer: the graph's vertex shader writing position/depth and normal/uv.
  #gbuffer(renderer, camera, water) {
    renderer.setRenderTarget(this.gbuffer);
    const gl = renderer.getContext();
    renderer.state.buffers.color.setMask(true);
    renderer.state.buffers.depth.setMask(true);
    gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, 1]);  // no water: depth (w) 1
    gl.clearBufferfv(gl.COLOR, 1, [0, 0, 0, 0]);
    renderer.clearDepth();
    renderer.autoClear = false;
    const mask = camera.layers.mask;
    camera.layers.enableAll();
    renderer.render(water.gbufferScene, camera);
    camera.layers.mask = mask;
    renderer.autoClear = true;
  }
}
