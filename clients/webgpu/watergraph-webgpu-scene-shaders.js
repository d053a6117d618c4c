// The runtime's own shaders (sky, lit opaque scene, deferred water's G-buffer) for the WebGPU
// runner. watergraph's WGSL emitter writes the graph's shaders; these few are the runtime's,
// which the scene description (`watergraph scene`) carries as GLSL ES 3.00. They are put in the
// GLSL 4.50 form naga's GLSL front end reads (one uniform block at group 0 binding 0, locations on
// every varying, gl_VertexIndex) and translated to WGSL by naga (npm naga-wasm, the validator this
// client already pins). Each vertex stage then converts its clip position as the graph's vs_main
// does (manifest "webgpu".conventions: y negated, z' = (z + w) / 2), so every target shares the
// graph's conventions: row 0 is the view's bottom row, depths are OpenGL's window depths.
// ES 3.00 has no clip distances: the opaque fragment shader discards on the clipped side of
// u_clip_plane (the desktop runtime clips with gl_ClipDistance; the two differ within a pixel).
export class SceneShaderError extends Error {
  constructor(message) {
    super(message);
    this.name = 'SceneShaderError';
  }
}

// Which description shader is which stage.
const STAGES = { sky_vertex: 'vertex', sky_fragment: 'fragment', opaque_vertex: 'vertex', opaque_fragment: 'fragment',
  water_gbuffer_fragment: 'fragment' };

// The uniform block's members in declaration order with their std140 offsets, which the
// runner fills (a mat4 at 0, then vectors each 16-byte aligned: every program here has a
// mat4 first and vec3/vec4 after).
function blockLayout(members) {
  let offset = 0;
  const layout = [];
  for (const { type, name } of members) {
    if (!['mat4', 'vec4', 'vec3'].includes(type)) throw new SceneShaderError(`runtime uniform ${name}: type ${type} has no layout here`);
    layout.push({ name, type, offset });
    offset += type === 'mat4' ? 64 : 16;
  }
  return { members: layout, size: offset };
}

// One ES 3.00 shader of the description as naga-readable GLSL 4.50. `inputs` gives the
// location of each `in` varying declared without one (the G-buffer reads the graph's
// varyings at the locations of the manifest's "webgpu".varyings).
export function glsl450ForNaga(name, source, inputs = {}) {
  const stage = STAGES[name];
  if (!stage) throw new SceneShaderError(`the scene description has no runtime shader '${name}' this runner uses`);
  const head = /^#version 300 es\n(?:precision \w+ \w+;\n)*/.exec(source);
  if (!head) throw new SceneShaderError(`${name} does not start with "#version 300 es"`);
  let body = source.slice(head[0].length);
  const members = [];
  let blockAt = -1;
  body = body.replace(/^uniform (\w+) (\w+);\n/gm, (line, type, uniform, at) => {
    members.push({ type, name: uniform });
    if (blockAt < 0) blockAt = at;
    return '';
  });
  if (members.length) {
    const block = `layout(set = 0, binding = 0, std140) uniform WgRuntimeConstants {\n${members.map((m) => `  ${m.type} ${m.name};\n`).join('')}};\n`;
    body = body.slice(0, blockAt) + block + body.slice(blockAt);
  }
  body = body.replace('#define WG_LOCATION(n)\n', '#define WG_LOCATION(n) layout(location = n)\n')
    .replace('#define WG_VERTEX_ID gl_VertexID\n', '#define WG_VERTEX_ID gl_VertexIndex\n');
  body = body.replace(/^in (\w+) (\w+);$/gm, (line, type, varying) => {
    if (!(varying in inputs)) throw new SceneShaderError(`${name}: no location for its input ${varying}`);
    return `layout(location = ${inputs[varying]}) in ${type} ${varying};`;
  });
  if (stage === 'vertex') {
    if (!/\bvoid main\(\) \{/.test(body)) throw new SceneShaderError(`${name} has no main()`);
    body = body.replace(/\bvoid main\(\) \{/, 'void wg_runtime_main() {') +
      '\nvoid main() {\n  wg_runtime_main();\n' +
      '  gl_Position = vec4(gl_Position.x, -gl_Position.y, 0.5 * (gl_Position.z + gl_Position.w), gl_Position.w);\n}\n';
  }
  return { stage, glsl: `#version 450\n${body}`, uniforms: blockLayout(members) };
}

// Every runtime shader the passes use, as WGSL modules (entry point "main") with their uniform
// block's layout: {sky_vertex: {wgsl, uniforms}, ...}. `naga` is the naga-wasm module (its
// init() already awaited in a browser); `gbufferInputs` maps v_world_position, v_normal and
// v_uv to the graph's varying locations (needed only for deferred water). Throws
// SceneShaderError with naga's message when a shader does not translate.
export function sceneShadersWgsl(description, naga, gbufferInputs = null) {
  const out = {};
  for (const name of Object.keys(STAGES)) {
    if (name === 'water_gbuffer_fragment' && !gbufferInputs) continue;
    const source = description.shaders?.[name];
    if (typeof source !== 'string') throw new SceneShaderError(`the scene description has no shader '${name}'`);
    const { stage, glsl, uniforms } = glsl450ForNaga(name, source, gbufferInputs ?? {});
    let module, info;
    try {
      module = naga.parseGlsl(glsl, { stage });
      info = naga.validate(module);
      out[name] = { wgsl: naga.writeWgsl(module, info, {}), uniforms };
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
