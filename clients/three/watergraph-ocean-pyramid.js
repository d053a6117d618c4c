// A filtered cascade's maps in WebGL 2 (a cascade whose "moments" map a shader reads): the
// displacement map, and the slope and moments maps with mip pyramids down to 1 x 1, written
// by the runtime's ocean_pack_filtered (level 0 of all three at once) and ocean_downsample
// (level l from level l - 1, for l = 1..L), as runtime/ocean_gpu_cascade.cpp does.
//
// Why raw WebGL here and three.js everywhere else: three.js renders into a mip level of one
// colour attachment only (setRenderTarget's activeMipmapLevel binds a scratch framebuffer
// with COLOR_ATTACHMENT0), while each downsample draws two levels at once (slopes and
// moments), and a sampler must show level l - 1 alone (TEXTURE_BASE_LEVEL = TEXTURE_MAX_LEVEL
// = l - 1) while level l is drawn. So these textures, their framebuffers and the two programs
// are made with the renderer's own context; three.js reads the textures as ExternalTextures
// and forgets its cached GL state after (renderer.resetState()). The maps are never made by
// glGenerateMipmap: its filter is the implementation's, and WebGL refuses it for RGBA32F.
import * as THREE from 'three';
import { WaterGraphError } from './watergraph-error.js';
import { downsampleDraws, pyramidLevels } from './watergraph-ocean-plan.js';

export { downsampleDraws, pyramidLevels };

function compile(gl, type, text, name) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, text);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
    const log = gl.getShaderInfoLog(shader);
    gl.deleteShader(shader);
    throw new WaterGraphError(`WebGL could not compile the runtime's ${name}: ${log}`);
  }
  return shader;
}

// A program of the description's fullscreen_vertex and fragment shader `name`, with its
// samplers on units 0, 1, ... in `samplers`' order.
function passProgram(gl, description, name, samplers) {
  const text = description.shaders?.[name], vertexText = description.shaders?.fullscreen_vertex;
  if (typeof text !== 'string' || typeof vertexText !== 'string')
    throw new WaterGraphError(`the scene description has no shader '${name}' (write it with a watergraph that filters ocean maps)`);
  const vertex = compile(gl, gl.VERTEX_SHADER, vertexText, 'fullscreen_vertex');
  const fragment = compile(gl, gl.FRAGMENT_SHADER, text, name);
  const program = gl.createProgram();
  gl.attachShader(program, vertex);
  gl.attachShader(program, fragment);
  gl.linkProgram(program);
  gl.deleteShader(vertex);
  gl.deleteShader(fragment);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS))
    throw new WaterGraphError(`WebGL could not link the runtime's ${name}: ${gl.getProgramInfoLog(program)}`);
  gl.useProgram(program);
  samplers.forEach((s, unit) => gl.uniform1i(gl.getUniformLocation(program, s), unit));
  return program;
}

// An RGBA32F texture of `levels` levels (immutable storage), nearest, repeating.
function floatTexture(gl, n, levels) {
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  gl.texStorage2D(gl.TEXTURE_2D, levels, gl.RGBA32F, n, n);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.REPEAT);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.REPEAT);
  return t;
}

function framebuffer(gl, attachments, level) {
  const f = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, f);
  attachments.forEach((t, i) => gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, t, level));
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  if (status !== gl.FRAMEBUFFER_COMPLETE)
    throw new WaterGraphError(`a filtered ocean cascade's framebuffer (level ${level}) is incomplete (0x${status.toString(16)}): the context cannot render RGBA32F`);
  return f;
}

// The programs, shared by every filtered cascade of a simulation.
export class PyramidPrograms {
  constructor(description) {
    this.description = description;
    this.gl = null;
  }

  init(gl) {
    if (this.gl === gl) return;
    this.gl = gl;
    this.pack = passProgram(gl, this.description, 'ocean_pack_filtered', ['u_a', 'u_b']);
    this.packLambda = gl.getUniformLocation(this.pack, 'u_lambda');
    this.downsample = passProgram(gl, this.description, 'ocean_downsample', ['u_slopes', 'u_moments']);
    this.vao = gl.createVertexArray();  // the full-screen triangle reads gl_VertexID alone
  }

  // One full-screen draw of `program` into `target` (size x size) with `textures` on units 0, 1.
  draw(program, target, attachments, size, textures) {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, target);
    gl.drawBuffers(Array.from({ length: attachments }, (_, i) => gl.COLOR_ATTACHMENT0 + i));
    gl.viewport(0, 0, size, size);
    for (const cap of [gl.BLEND, gl.DEPTH_TEST, gl.STENCIL_TEST, gl.SCISSOR_TEST, gl.CULL_FACE,
      gl.POLYGON_OFFSET_FILL, gl.SAMPLE_ALPHA_TO_COVERAGE, gl.RASTERIZER_DISCARD]) gl.disable(cap);
    gl.colorMask(true, true, true, true);
    gl.useProgram(program);
    gl.bindVertexArray(this.vao);
    textures.forEach((t, unit) => {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindSampler(unit, null);
      gl.bindTexture(gl.TEXTURE_2D, t);
    });
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  dispose() {
    if (!this.gl) return;
    this.gl.deleteProgram(this.pack);
    this.gl.deleteProgram(this.downsample);
    this.gl.deleteVertexArray(this.vao);
    this.gl = null;
  }
}

// One filtered cascade's three maps. texture(which) gives the three.js textures the water
// material binds (their GL textures exist from the first update on).
export class OceanPyramid {
  constructor(n) {
    this.n = n;
    this.levels = pyramidLevels(n);
    this.gl = null;
    this.textures = [new THREE.ExternalTexture(null), new THREE.ExternalTexture(null), new THREE.ExternalTexture(null)];
  }

  #init(gl) {
    if (this.gl === gl) return;
    this.gl = gl;
    const n = this.n;
    this.maps = [floatTexture(gl, n, 1), floatTexture(gl, n, this.levels), floatTexture(gl, n, this.levels)];
    this.maps.forEach((t, i) => { this.textures[i].sourceTexture = t; });
    this.packTarget = framebuffer(gl, this.maps, 0);
    this.levelTargets = downsampleDraws(n).map((d) => framebuffer(gl, [this.maps[1], this.maps[2]], d.level));
  }

  // Shows only levels [base, max] of the slope and moments maps to a sampler.
  #levels(base, max) {
    const gl = this.gl;
    for (const t of [this.maps[1], this.maps[2]]) {
      gl.bindTexture(gl.TEXTURE_2D, t);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_BASE_LEVEL, base);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAX_LEVEL, max);
    }
  }

  // ocean_pack_filtered from the transformed spectra (three.js textures a and b), then the
  // pyramids, level by level; three.js's cached GL state is reset after.
  update(renderer, programs, a, b, lambda) {
    const gl = renderer.getContext();
    try {
      programs.init(gl);
      this.#init(gl);
      const raw = (t) => renderer.properties.get(t).__webglTexture;
      gl.useProgram(programs.pack);
      gl.uniform1f(programs.packLambda, lambda);
      programs.draw(programs.pack, this.packTarget, 3, this.n, [raw(a), raw(b)]);
      for (const d of downsampleDraws(this.n)) {
        // Level l - 1 alone is visible to the samplers while level l is drawn: no feedback loop.
        this.#levels(d.source, d.source);
        programs.draw(programs.downsample, this.levelTargets[d.level - 1], 2, d.size, [this.maps[1], this.maps[2]]);
      }
      this.#levels(0, this.levels - 1);  // the water shader fetches every level
    } finally {
      renderer.resetState();
    }
  }

  dispose() {
    if (!this.gl) return;
    const gl = this.gl;
    for (const t of this.maps) gl.deleteTexture(t);
    for (const f of [this.packTarget, ...this.levelTargets]) gl.deleteFramebuffer(f);
    this.textures.forEach((t) => { t.sourceTexture = null; });
    this.gl = null;
  }
}
