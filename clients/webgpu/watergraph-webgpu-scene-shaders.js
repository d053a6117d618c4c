// The runtime's own shaders (sky, lit opaque scene, deferred water's G-buffer) for the WebGPU
// runner. watergraph's WGSL emitter writes the graph's shaders; these few are the runtime's,
// which the scene description (`watergraph scene`) carries in their WebGPU form
// (description.webgpu.shaders, runtime/webgpu_shader_form.h, docs/webgpu.md): GLSL 4.50 that
// naga's GLSL front end reads as it is, with a declaration table (the uniform block's members
// and byte offsets, textures, samplers, varyings' locations). naga (npm naga-wasm, the validator
// this client already pins) translates the text to WGSL unchanged; the runner lays out the
// uniform buffer from the table and never reads the shader text. The runtime wrote each vertex
// stage to convert its clip position as the graph's vs_main does (manifest
// "webgpu".conventions: y negated, z' = (z + w) / 2), so every target shares the graph's
// conventions: row 0 is the view's bottom row, depths are OpenGL's window depths. WebGPU has
// no clip distances here: the opaque fragment shader discards on the clipped side of
// u_clip_plane (the desktop runtime clips with gl_ClipDistance; the two differ within a pixel).
export class SceneShaderError extends Error {
  constructor(message) {
    super(message);
    this.name = 'SceneShaderError';
  }
}

// The description shaders the runner draws with.
const SCENE_SHADERS = ['sky_vertex', 'sky_fragment', 'opaque_vertex', 'opaque_fragment', 'water_gbuffer_fragment'];

// The WebGPU form of a description shader: {stage, entry_point, glsl, uniform_block, textures,
// samplers, inputs, outputs}.
export function webgpuFormOf(description, name) {
  const form = description.webgpu?.shaders?.[name];
  if (!form || typeof form.glsl !== 'string')
    throw new SceneShaderError(`the scene description has no WebGPU form of '${name}' (description.webgpu.shaders: write it with this watergraph's \`scene\`)`);
  return form;
}

// The naga defines that place a form's inputs whose locations the host chooses (the G-buffer
// reads the graph's varyings where its vertex stage writes them): `locations` maps each such
// input's name to its location.
export function locationDefines(name, form, locations) {
  const defines = {};
  for (const input of form.inputs) {
    if (!input.define) continue;
    if (!(input.name in locations)) throw new SceneShaderError(`${name}: no location for its input ${input.name}`);
    defines[input.define] = String(locations[input.name]);
  }
  return defines;
}

// A form's uniform block as the runner fills it: {members: [{name, type, offset}], size}.
function blockLayout(form) {
  const block = form.uniform_block;
  return block ? { members: block.members.map(({ name, type, offset }) => ({ name, type, offset })), size: block.size }
    : { members: [], size: 0 };
}

// Every runtime shader the passes use, as WGSL modules (entry point "main") with their uniform
// block's layout: {sky_vertex: {wgsl, uniforms}, ...}. `naga` is the naga-wasm module (its
// init() already awaited in a browser); `gbufferInputs` maps v_world_position, v_normal and
// v_uv to the graph's varying locations (needed only for deferred water). Throws
// SceneShaderError with naga's message when a shader does not translate.
export function sceneShadersWgsl(description, naga, gbufferInputs = null) {
  const out = {};
  for (const name of SCENE_SHADERS) {
    if (name === 'water_gbuffer_fragment' && !gbufferInputs) continue;
    const form = webgpuFormOf(description, name);
    const defines = locationDefines(name, form, gbufferInputs ?? {});
    let module, info;
    try {
      module = naga.parseGlsl(form.glsl, { stage: form.stage, defines });
      info = naga.validate(module);
      out[name] = { wgsl: naga.writeWgsl(module, info, {}), uniforms: blockLayout(form) };
    } catch (e) {
      const text = String(e.formatted || e.message || e).replace(/\u001b\[[0-9;]*m/g, '');
      throw new SceneShaderError(`naga could not translate the runtime's ${name}: ${text.split('\n').slice(0, 6).join(' ')}`);
    } finally {
      info?.free?.();
      module?.free?.();
    }
  }
  return out;
}

// What deferred water's G-buffer reads from a compiled graph: its varyings' WGSL locations
// (sceneShadersWgsl's `gbufferInputs`), or null when the manifest has no deferred water.
export function gbufferInputsOf(manifest) {
  return manifest.passes.includes('deferred_water')
    ? Object.fromEntries(manifest.webgpu.varyings.map((v) => [v.name, v.location])) : null;
}

// One description's scene shaders through naga, translated once per set of G-buffer inputs:
// a page drawing many graphs in one scene translates each shader once.
export class SceneShaderCache {
  constructor(description, naga) {
    this.description = description;
    this.naga = naga;
    this.byInputs = new Map();
  }

  forManifest(manifest) {
    const gbufferInputs = gbufferInputsOf(manifest);
    const key = JSON.stringify(gbufferInputs);
    if (!this.byInputs.has(key)) this.byInputs.set(key, sceneShadersWgsl(this.description, this.naga, gbufferInputs));
    return this.byInputs.get(key);
  }
}
