// The scene side of the WebGPU runner: the render targets of a pass plan and the runtime's
// scene passes (runtime/renderer.cpp: environment cube, depth pre-pass, planar reflection,
// refraction, opaque scene, scene colour copy), drawn with the runtime's own shaders
// (watergraph-webgpu-scene-shaders.js) over the scene description's mesh. Matrices are
// OpenGL's, column-major, as the runtime's glm ones; every shader converts its clip position to
// WebGPU's, so every target keeps the graph's conventions (row 0 at the view's bottom).
export class WebgpuPassError extends Error {
  constructor(message) {
    super(message);
    this.name = 'WebgpuPassError';
  }
}

// --- 4x4 matrices, column-major arrays of 16 numbers (glm's layout).
export function mat4Multiply(a, b) {
  const out = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c)
    for (let r = 0; r < 4; ++r)
      for (let k = 0; k < 4; ++k) out[4 * c + r] += a[4 * k + r] * b[4 * c + k];
  return out;
}

// The inverse by Gauss-Jordan elimination with partial pivoting (a singular matrix throws).
export function mat4Inverse(m) {
  const a = [0, 1, 2, 3].map((r) => [0, 1, 2, 3].map((c) => m[4 * c + r]).concat([0, 1, 2, 3].map((c) => (c === r ? 1 : 0))));
  for (let col = 0; col < 4; ++col) {
    let pivot = col;
    for (let r = col + 1; r < 4; ++r) if (Math.abs(a[r][col]) > Math.abs(a[pivot][col])) pivot = r;
    if (a[pivot][col] === 0) throw new WebgpuPassError('a camera matrix is singular');
    [a[col], a[pivot]] = [a[pivot], a[col]];
    const p = a[col][col];
    for (let c = 0; c < 8; ++c) a[col][c] /= p;
    for (let r = 0; r < 4; ++r) {
      if (r === col) continue;
      const f = a[r][col];
      for (let c = 0; c < 8; ++c) a[r][c] -= f * a[col][c];
    }
  }
  const out = new Array(16);
  for (let r = 0; r < 4; ++r) for (let c = 0; c < 4; ++c) out[4 * c + r] = a[r][4 + c];
  return out;
}

// glm::perspective (right-handed, depth -1..1).
export function perspective(fovYDegrees, aspect, near, far) {
  const f = 1 / Math.tan((fovYDegrees * Math.PI) / 360);
  return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, -(far + near) / (far - near), -1, 0, 0, -(2 * far * near) / (far - near), 0];
}

// glm::lookAt from the origin along `direction` with `up` (right-handed).
export function lookAtFromOrigin(direction, up) {
  const norm = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const f = norm(direction), s = norm(cross(f, up)), u = cross(s, f);
  return [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0, 0, 0, 0, 1];
}

// Mirror about the water plane y = 0.
const MIRROR_Y = [1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
const NO_CLIP = [0, 0, 0, 1];

const TARGET_FORMATS = { rgba16f: 'rgba16float', rgba32f: 'rgba32float' };

// Which targets the water samples texel for texel (nearest, unfilterable in WebGPU): depth, the
// deferred G-buffer and RGBA32F (no float32-filterable here), as runtime/pass_plan.cpp's sampledNearest.
export function sampledNearest(target) {
  return !target.color || target.pass === 'deferred_water' || target.color === 'rgba32f';
}

// The GPU textures of a plan (clients/three's planPasses): each scene target's texture and the
// view the water samples, keyed by its sampler name (resources), plus the frame.
export function createTargets(device, plan) {
  const usage = GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_SRC | GPUTextureUsage.COPY_DST;
  const targets = {}, resources = {};
  for (const t of plan.targets) {
    if (t.name === 'display') continue;
    if (t.color && !TARGET_FORMATS[t.color]) throw new WebgpuPassError(`target ${t.name}: colour format ${t.color} is not in this runner`);
    const entry = { spec: t };
    if (t.cube) {
      entry.color = device.createTexture({ size: [t.width, t.height, 6], format: TARGET_FORMATS[t.color], usage });
      entry.view = entry.color.createView({ dimension: 'cube' });
    } else {
      if (t.color) entry.color = device.createTexture({ size: [t.width, t.height], format: TARGET_FORMATS[t.color], usage });
      if (t.depth) entry.depth = device.createTexture({ size: [t.width, t.height], format: 'depth32float', usage });
      entry.view = (entry.color ?? entry.depth).createView();
    }
    targets[t.name] = entry;
    if (t.sampler) resources[t.sampler] = { view: entry.view, cube: t.cube, nearest: sampledNearest(t),
      gbuffer: t.pass === 'deferred_water' ? TARGET_FORMATS[t.color] : null };
  }
  return { targets, resources };
}

// The runtime's scene draws: `shaders` from sceneShadersWgsl, `mesh` the description's.
export class ScenePasses {
  constructor(device, description, shaders) {
    this.device = device;
    this.description = description;
    this.sun = description.sun_direction;
    const module = (name) => device.createShaderModule({ code: shaders[name].wgsl, label: `runtime ${name}` });
    this.layout = device.createBindGroupLayout({
      entries: [{ binding: 0, visibility: GPUShaderStage.VERTEX | GPUShaderStage.FRAGMENT, buffer: { type: 'uniform' } }] });
    this.shaders = shaders;
    this.modules = { skyVertex: module('sky_vertex'), skyFragment: module('sky_fragment'),
      opaqueVertex: module('opaque_vertex'), opaqueFragment: module('opaque_fragment') };
    this.pipelines = new Map();
    const m = description.mesh;
    const stride = m.attributes.reduce((n, a) => n + a.components, 0);
    let offset = 0;
    this.meshLayout = { arrayStride: 4 * stride, attributes: m.attributes.map((a) => {
      const at = { shaderLocation: a.location, offset: 4 * offset, format: a.components === 1 ? 'float32' : `float32x${a.components}` };
      offset += a.components;
      return at;
    }) };
    const vertices = new Float32Array(m.vertices), indices = new Uint32Array(m.indices);
    this.vertexBuffer = device.createBuffer({ size: vertices.byteLength, usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
    device.queue.writeBuffer(this.vertexBuffer, 0, vertices);
    this.indexBuffer = device.createBuffer({ size: indices.byteLength, usage: GPUBufferUsage.INDEX | GPUBufferUsage.COPY_DST });
    device.queue.writeBuffer(this.indexBuffer, 0, indices);
    this.indexCount = indices.length;
  }

  // A pipeline per (program, colour format, depth): the runtime draws without culling, depth
  // LEQUAL; the sky writes no depth (it lies at the far plane, after the opaque scene).
  #pipeline(program, color, depth) {
    const key = `${program}/${color}/${depth}`;
    if (this.pipelines.has(key)) return this.pipelines.get(key);
    const sky = program === 'sky';
    const desc = {
      layout: this.device.createPipelineLayout({ bindGroupLayouts: [this.layout] }),
      vertex: { module: sky ? this.modules.skyVertex : this.modules.opaqueVertex, entryPoint: 'main', buffers: sky ? [] : [this.meshLayout] },
      primitive: { topology: 'triangle-list', cullMode: 'none' },
    };
    if (color) desc.fragment = { module: sky ? this.modules.skyFragment : this.modules.opaqueFragment, entryPoint: 'main', targets: [{ format: color }] };
    if (depth) desc.depthStencil = { format: 'depth32float', depthWriteEnabled: !sky, depthCompare: 'less-equal' };
    const p = this.device.createRenderPipeline(desc);
    this.pipelines.set(key, p);
    return p;
  }

  #uniforms(program, values) {
    const layout = this.shaders[program === 'sky' ? 'sky_vertex' : 'opaque_vertex'].uniforms;
    const data = new Float32Array(layout.size / 4);
    for (const m of layout.members) data.set(values[m.name], m.offset / 4);
    const buffer = this.device.createBuffer({ size: data.byteLength, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
    this.device.queue.writeBuffer(buffer, 0, data);
    return this.device.createBindGroup({ layout: this.layout, entries: [{ binding: 0, resource: { buffer } }] });
  }

  // The opaque scene keeping the side where dot(plane, (p, 1)) >= 0 (colorFormat null: depth only).
  drawOpaque(pass, colorFormat, viewProjection, plane) {
    pass.setPipeline(this.#pipeline('opaque', colorFormat, true));
    pass.setBindGroup(0, this.#uniforms('opaque', { u_view_projection: viewProjection, u_clip_plane: plane, u_sun_direction: this.sun }));
    pass.setVertexBuffer(0, this.vertexBuffer);
    pass.setIndexBuffer(this.indexBuffer, 'uint32');
    pass.drawIndexed(this.indexCount);
  }

  drawSky(pass, colorFormat, viewProjection, depth) {
    pass.setPipeline(this.#pipeline('sky', colorFormat, depth));
    pass.setBindGroup(0, this.#uniforms('sky', { u_inverse_view_projection: mat4Inverse(viewProjection), u_sun_direction: this.sun }));
    pass.draw(3);
  }
}

// At a reduced scale (manifest "pass_scales") the runtime's glBlitFramebuffer shrinks the
// frame with GL_LINEAR: each target pixel is the bilinear sample of the frame at its centre's
// place, which is what this full-screen pass samples (rows kept in memory order, no flip).
function shrinkInto(device, encoder, source, target) {
  const { width, height } = target.spec;
  const module = device.createShaderModule({ label: 'scene colour shrink', code: `
@group(0) @binding(0) var wg_frame: texture_2d<f32>;
@group(0) @binding(1) var wg_frame_sampler: sampler;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
  return vec4<f32>(select(-1.0, 3.0, i == 1u), select(-1.0, 3.0, i == 2u), 0.0, 1.0);
}
@fragment fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
  return textureSampleLevel(wg_frame, wg_frame_sampler, p.xy / vec2<f32>(${width}.0, ${height}.0), 0.0);
}
` });
  const pipeline = device.createRenderPipeline({ layout: 'auto', vertex: { module, entryPoint: 'vs' },
    fragment: { module, entryPoint: 'fs', targets: [{ format: target.color.format }] }, primitive: { topology: 'triangle-list' } });
  const sampler = device.createSampler({ magFilter: 'linear', minFilter: 'linear', addressModeU: 'clamp-to-edge', addressModeV: 'clamp-to-edge' });
  const group = device.createBindGroup({ layout: pipeline.getBindGroupLayout(0),
    entries: [{ binding: 0, resource: source.createView() }, { binding: 1, resource: sampler }] });
  const pass = encoder.beginRenderPass({ colorAttachments: [{ view: target.color.createView(), loadOp: 'clear', clearValue: [0, 0, 0, 1], storeOp: 'store' }] });
  pass.setPipeline(pipeline);
  pass.setBindGroup(0, group);
  pass.draw(3);
  pass.end();
}

// One colour-and-depth render pass into a target, cleared as the runtime's bindTarget
// (colour to the description's clear colour, depth to 1).
export function beginTargetPass(encoder, entry, clearColor, { colorView = null, load = false } = {}) {
  const color = colorView ?? entry.color?.createView();
  return encoder.beginRenderPass({
    colorAttachments: color ? [{ view: color, clearValue: clearColor, loadOp: load ? 'load' : 'clear', storeOp: 'store' }] : [],
    depthStencilAttachment: entry.depth ? { view: entry.depth.createView(), depthClearValue: 1, depthLoadOp: load ? 'load' : 'clear', depthStoreOp: 'store' } : undefined,
  });
}

// Runs one scene pass of the plan. `camera`: {view, projection, position} (GL matrices);
// `scene` null draws nothing (the runtime's `--scene none`: the targets are only cleared).
export function runScenePass(device, encoder, passName, { targets, scene, camera, description, frameFormat }) {
  const clear = description?.clear_color ?? [0, 0, 0, 1];
  const viewProjection = mat4Multiply(camera.projection, camera.view);
  const side = camera.position[1] >= 0 ? 1 : -1;  // the camera's side of the water
  const colorPass = (name, draw) => {
    const entry = targets[name];
    const pass = beginTargetPass(encoder, entry, clear);
    if (scene) draw(pass, entry.color ? TARGET_FORMATS[entry.spec.color] : null);
    pass.end();
  };
  switch (passName) {
    case 'environment_cubemap': {
      const env = description.environment, entry = targets.environment;
      const projection = perspective(env.fov_y_degrees, 1, env.near, env.far);
      env.faces.forEach((face, f) => {
        const view = entry.color.createView({ dimension: '2d', baseArrayLayer: f, arrayLayerCount: 1 });
        const pass = encoder.beginRenderPass({ colorAttachments: [{ view, clearValue: clear, loadOp: 'clear', storeOp: 'store' }] });
        if (scene) scene.drawSky(pass, TARGET_FORMATS[entry.spec.color], mat4Multiply(projection, lookAtFromOrigin(face.direction, face.up)), false);
        pass.end();
      });
      return;
    }
    case 'depth_prepass':
      return colorPass('scene_depth', (pass) => scene.drawOpaque(pass, null, viewProjection, NO_CLIP));
    case 'planar_reflection':
      // The camera mirrored about y = 0; only what is on the camera's side of the water is reflected.
      return colorPass('reflection', (pass, format) => {
        const mirrored = mat4Multiply(viewProjection, MIRROR_Y);
        scene.drawOpaque(pass, format, mirrored, [0, side, 0, 0]);
        scene.drawSky(pass, format, mirrored, true);
      });
    case 'refraction':
      return colorPass('refraction', (pass, format) => {
        scene.drawOpaque(pass, format, viewProjection, [0, -side, 0, 0]);
        scene.drawSky(pass, format, viewProjection, true);
      });
    case 'opaque_scene':
      return colorPass('frame', (pass) => {
        scene.drawOpaque(pass, frameFormat, viewProjection, NO_CLIP);
        scene.drawSky(pass, frameFormat, viewProjection, true);
      });
    case 'scene_color_copy': {
      const from = targets.frame, to = targets.scene_color;
      if (from.spec.width === to.spec.width && from.spec.height === to.spec.height)
        encoder.copyTextureToTexture({ texture: from.color }, { texture: to.color }, [to.spec.width, to.spec.height]);
      else
        shrinkInto(device, encoder, from.color, to);
      return;
    }
    default:
      throw new WebgpuPassError(`this runner has no scene pass '${passName}'`);
  }
}
