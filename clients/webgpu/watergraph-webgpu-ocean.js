// The spectral ocean's simulation pass (a manifest's "ocean_simulation") for the WebGPU
// runner: the same passes as the runtime and the three.js client
// (clients/three/watergraph-ocean.js), in the same order, running the runtime's own pass
// shaders — the scene description's GLSL ES texts (ocean_evolve, ocean_stockham, ...),
// translated to WGSL by naga as the runner's scene shaders are — as full-screen fragment
// passes into rgba32float and r32float textures. What only the compiler knows comes from the
// graph's ocean module (<graph>.ocean.js): each cascade's h0 and frequency indices, the
// twiddles, the 32-bit time phase, the foam's constants and clock.
import { cascadeMaps, cascadePasses, OCEAN_MAPS, pyramidLevels } from '../three/watergraph-ocean-plan.js';

// The plan's names, from the module both web clients share (clients/three, served as /three/).
export { cascadePasses, pyramidLevels };

export class WebgpuOceanError extends Error {
  constructor(message) {
    super(message);
    this.name = 'WebgpuOceanError';
  }
}

const OCEAN_PASS_SHADERS = ['ocean_evolve', 'ocean_evolve_displacement', 'ocean_evolve_jacobian', 'ocean_stockham',
  'ocean_stockham_single', 'ocean_pack', 'ocean_pack_displacement', 'ocean_foam_step', 'ocean_foam_blend',
  'ocean_pack_filtered', 'ocean_downsample'];
const SCALARS = { float: 'setFloat32', int: 'setInt32', uint: 'setUint32' };

// A pass shader's WebGPU form from the description (description.webgpu.shaders[name]:
// runtime/webgpu_shader_form.h), as this runner binds it: its scalar uniforms with their
// offsets in the block at binding 0, each texture's binding and sample type, the nearest
// sampler's binding (every look-up is texelFetch, which naga writes as textureLoad).
export function oceanPassForm(description, name) {
  const form = description.webgpu?.shaders?.[name];
  if (!form || typeof form.glsl !== 'string')
    throw new WebgpuOceanError(`the scene description has no WebGPU form of '${name}' (description.webgpu.shaders)`);
  const block = form.uniform_block;
  return {
    glsl: form.glsl,
    uniforms: block ? block.members.map(({ name, type, offset }) => ({ name, type, offset })) : [],
    size: block ? block.size : 16,
    textures: form.textures.map((t) => ({ name: t.name, binding: t.binding, sampleType: t.sample_type })),
    samplerBinding: form.samplers[0]?.binding,
  };
}

// Every pass shader of the description as {wgsl, uniforms, textures, samplerBinding, size}.
export function oceanPassesWgsl(description, naga) {
  const out = {};
  for (const name of OCEAN_PASS_SHADERS) {
    const pass = oceanPassForm(description, name);
    let module, info;
    try {
      module = naga.parseGlsl(pass.glsl, { stage: 'fragment' });
      info = naga.validate(module);
      out[name] = { ...pass, wgsl: naga.writeWgsl(module, info, {}) };
    } catch (e) {
      const text = String(e.formatted || e.message || e).replace(/\u001b\[[0-9;]*m/g, '');
      throw new WebgpuOceanError(`naga could not translate the runtime's ${name}: ${text.split('\n').slice(0, 6).join(' ')}`);
    } finally {
      info?.free?.();
      module?.free?.();
    }
  }
  return out;
}

// The full-screen triangle every pass is drawn with.
const FULLSCREEN_WGSL = '@vertex fn main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {\n' +
  '  return vec4<f32>(select(-1.0, 3.0, i == 1u), select(-1.0, 3.0, i == 2u), 0.0, 1.0);\n}\n';

const USAGE = () => GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_DST | GPUTextureUsage.COPY_SRC;

// The colour bytes a sample of ocean_pack_filtered's three RGBA32F targets.
const FILTERED_PACK_BYTES = 48;

// One level of a texture, as a render target or as what a sampler shows (its level 0).
const mipOf = (texture, mip) => ({ texture, mip });
const viewOf = (t) => (t.texture ? t.texture.createView({ baseMipLevel: t.mip, mipLevelCount: 1 }) : t.createView());

// Every ocean of a manifest on `device`. Call encode() with a command encoder for a frame's
// time (its passes are recorded there, before the water's), then map() gives each ocean
// texture's view.
export class WebgpuOceanSimulation {
  constructor(device, manifest, module, passes) {
    if (!module || !Array.isArray(module.oceans) || module.oceans.length !== manifest.oceans.length)
      throw new WebgpuOceanError(`graph '${manifest.graph}': its ocean module does not describe the manifest's oceans`);
    this.device = device;
    this.module = module;
    this.passes = passes;
    // ocean_pack_filtered writes three RGBA32F targets at once: 48 bytes a sample, over
    // WebGPU's default limit of 32 (request the adapter's maxColorAttachmentBytesPerSample).
    const filtered = manifest.oceans.some((o) => o.filtered === true);
    const bytes = device.limits?.maxColorAttachmentBytesPerSample ?? 32;
    if (filtered && bytes < FILTERED_PACK_BYTES)
      throw new WebgpuOceanError(`graph '${manifest.graph}' filters its ocean maps, whose pack writes ${FILTERED_PACK_BYTES} bytes of colour a sample; ` +
        `this device allows ${bytes} (request maxColorAttachmentBytesPerSample ${FILTERED_PACK_BYTES} or more from the adapter)`);
    this.sampler = device.createSampler({ magFilter: 'nearest', minFilter: 'nearest' });
    this.vertex = device.createShaderModule({ code: FULLSCREEN_WGSL, label: 'the ocean passes\' full-screen triangle' });
    this.pipelines = {};
    this.oceans = module.oceans.map((data, o) => {
      if (data.node !== manifest.oceans[o].node) throw new WebgpuOceanError(`ocean ${o}: the module's node '${data.node}' is not the manifest's`);
      const packed = data.cascades();
      const twiddles = new Map();  // one texture per cascade size
      const cascades = data.tileLengths.map((_, c) => {
        const n = data.sizes[c];  // the cascade's own N (cascade_sizes)
        if (!twiddles.has(n)) twiddles.set(n, this.#texture(n / 2, 1, 'rg32float', module.twiddles(n), 8));
        const twiddle = twiddles.get(n);
        // The manifest's "filtered" (the compiler's): every cascade of the ocean keeps pyramids.
        const { slopes, foam, filtered } = cascadeMaps(manifest, o, c);
        if (foam && c >= data.foam.cascades) throw new WebgpuOceanError(`ocean ${data.node} cascade ${c} makes no foam`);
        const rgba = (levels = 1) => this.#texture(n, n, 'rgba32float', null, 0, levels);
        return {
          n, slopes, filtered, twiddle, dk: data.dk[c],
          plan: cascadePasses(n, { slopes, filtered }),
          h0: this.#texture(n, n, 'rgba32float', packed[c].h0, 16),
          frequency: this.#texture(n, n, 'r32uint', packed[c].frequency, 4),
          spectra: [[rgba(), slopes ? rgba() : null], [rgba(), slopes ? rgba() : null]],
          maps: filtered ? [rgba(), rgba(pyramidLevels(n)), rgba(pyramidLevels(n))] : [rgba(), slopes ? rgba() : null],
          jacobian: foam ? [rgba(), rgba()] : null,
          foam: foam ? { states: [0, 1, 2].map(() => this.#texture(n, n, 'r32float')), output: this.#texture(n, n, 'r32float'),
            current: 0, next: 1, valid: false, at: 0 } : null,
        };
      });
      return { data, cascades };
    });
  }

  #texture(width, height, format, data = null, bytesPerTexel = 0, mipLevelCount = 1) {
    const t = this.device.createTexture({ size: [width, height], format, usage: USAGE(), mipLevelCount });
    if (data) this.device.queue.writeTexture({ texture: t }, data, { bytesPerRow: width * bytesPerTexel }, [width, height]);
    return t;
  }

  #pipeline(name, formats) {
    const key = `${name} ${formats.join(' ')}`;
    if (!this.pipelines[key]) {
      const pass = this.passes[name];
      const entries = [];
      if (pass.uniforms.length) entries.push({ binding: 0, visibility: GPUShaderStage.FRAGMENT, buffer: { type: 'uniform' } });
      for (const t of pass.textures) entries.push({ binding: t.binding, visibility: GPUShaderStage.FRAGMENT, texture: { sampleType: t.sampleType } });
      entries.push({ binding: pass.samplerBinding, visibility: GPUShaderStage.FRAGMENT, sampler: { type: 'non-filtering' } });
      const layout = this.device.createBindGroupLayout({ entries });
      const module = this.device.createShaderModule({ code: pass.wgsl, label: name });
      const pipeline = this.device.createRenderPipeline({
        layout: this.device.createPipelineLayout({ bindGroupLayouts: [layout] }),
        vertex: { module: this.vertex, entryPoint: 'main' },
        fragment: { module, entryPoint: 'main', targets: formats.map((format) => ({ format })) },
        primitive: { topology: 'triangle-list' },
      });
      this.pipelines[key] = { pipeline, layout, pass };
    }
    return this.pipelines[key];
  }

  // One full-screen draw of `name` into `targets` with `values` (uniforms and textures by
  // name). A target or texture is a texture (its only level) or mipOf(texture, mip).
  #draw(encoder, name, values, targets) {
    const { pipeline, layout, pass } = this.#pipeline(name, targets.map((t) => (t.texture ?? t).format));
    const entries = [];
    if (pass.uniforms.length) {
      const buffer = this.device.createBuffer({ size: pass.size, usage: GPUBufferUsage.UNIFORM, mappedAtCreation: true });
      const view = new DataView(buffer.getMappedRange());
      for (const u of pass.uniforms) {
        if (values[u.name] === undefined) throw new WebgpuOceanError(`${name}: no value for ${u.name}`);
        view[SCALARS[u.type]](u.offset, values[u.name], true);
      }
      buffer.unmap();
      entries.push({ binding: 0, resource: { buffer } });
    }
    for (const t of pass.textures) {
      if (!values[t.name]) throw new WebgpuOceanError(`${name}: no texture for ${t.name}`);
      entries.push({ binding: t.binding, resource: viewOf(values[t.name]) });
    }
    entries.push({ binding: pass.samplerBinding, resource: this.sampler });
    const p = encoder.beginRenderPass({
      colorAttachments: targets.map((t) => ({ view: viewOf(t), loadOp: 'clear', clearValue: [0, 0, 0, 0], storeOp: 'store' })),
    });
    p.setPipeline(pipeline);
    p.setBindGroup(0, this.device.createBindGroup({ layout, entries }));
    p.draw(3);
    p.end();
  }

  #evolve(encoder, c, shader, tau, targets) {
    this.#draw(encoder, shader, { u_h0: c.h0, u_frequency: c.frequency, u_tau: tau, u_dk: c.dk, u_n: c.n }, targets);
  }

  // The Stockham stages from spectra[0] ping-ponging; returns the index holding the result.
  #transform(encoder, c, shader, spectra) {
    let current = 0;
    for (let vertical = 0; vertical < 2; ++vertical)
      for (let ns = 1; ns < c.n; ns *= 2) {
        const [a, b] = spectra[current];
        this.#draw(encoder, shader, { u_a: a, u_b: b, u_twiddle: c.twiddle, u_n: c.n, u_ns: ns, u_vertical: vertical },
          spectra[1 - current].filter(Boolean));
        current = 1 - current;
      }
    return current;
  }

  // The passes of c.plan (cascadePasses) in order. A downsample samples views of level l - 1
  // and draws into views of level l: different subresources, so no conflict.
  #cascade(encoder, c, tau, choppiness) {
    let current = 0;  // the spectra pair holding the last result
    for (const p of c.plan) {
      const [a, b] = c.spectra[current];
      if (p.shader.startsWith('ocean_evolve')) {
        this.#evolve(encoder, c, p.shader, tau, c.spectra[0].filter(Boolean));
        current = 0;
      } else if (p.shader.startsWith('ocean_stockham')) {
        this.#draw(encoder, p.shader, { u_a: a, u_b: b, u_twiddle: c.twiddle, u_n: c.n, u_ns: p.ns, u_vertical: p.vertical },
          c.spectra[1 - current].filter(Boolean));
        current = 1 - current;
      } else if (p.shader === 'ocean_pack_filtered') {
        this.#draw(encoder, p.shader, { u_a: a, u_b: b, u_lambda: choppiness }, [c.maps[0], mipOf(c.maps[1], 0), mipOf(c.maps[2], 0)]);
      } else if (p.shader === 'ocean_downsample') {
        this.#draw(encoder, p.shader, { u_slopes: mipOf(c.maps[1], p.source), u_moments: mipOf(c.maps[2], p.source) },
          [mipOf(c.maps[1], p.level), mipOf(c.maps[2], p.level)]);
      } else {
        this.#draw(encoder, p.shader, { u_a: a, u_b: b, u_lambda: choppiness }, c.maps.filter(Boolean));
      }
    }
  }

  #jacobianFields(encoder, c, tau) {
    const spectra = c.jacobian.map((t) => [t, null]);
    this.#evolve(encoder, c, 'ocean_evolve_jacobian', tau, [c.jacobian[0]]);
    return c.jacobian[this.#transform(encoder, c, 'ocean_stockham_single', spectra)];
  }

  #foamStep(encoder, c, foamSettings, m, choppiness) {
    const f = c.foam;
    const fields = this.#jacobianFields(encoder, c, this.module.phaseTau(m * foamSettings.step));
    const written = 3 - f.current - f.next;
    this.#draw(encoder, 'ocean_foam_step', {
      u_fields: fields, u_previous: f.states[f.next], u_lambda: choppiness,
      u_keep: foamSettings.keep, u_gain: foamSettings.gain, u_threshold: foamSettings.threshold,
    }, [f.states[written]]);
    f.current = f.next;
    f.next = written;
  }

  // As OceanGpuFoam::update with a replay (a still frame's foam, as `watergraph render`), or
  // continued from the held steps.
  #foam(encoder, c, foamSettings, time, choppiness, history) {
    const f = c.foam;
    const n = this.module.foamStepIndex(foamSettings, time), k = foamSettings.historySteps;
    const continues = f.valid && n >= f.at && (n === f.at || (history === 'continue' && n - f.at <= k));
    if (continues) {
      for (let m = f.at + 2; m <= n + 1; ++m) this.#foamStep(encoder, c, foamSettings, m, choppiness);
    } else {
      const clear = encoder.beginRenderPass({ colorAttachments: [{ view: f.states[f.next].createView(), loadOp: 'clear', clearValue: [0, 0, 0, 0], storeOp: 'store' }] });
      clear.end();
      for (let m = n - k + 1; m <= n + 1; ++m) this.#foamStep(encoder, c, foamSettings, m, choppiness);
    }
    f.valid = true;
    f.at = n;
    this.#draw(encoder, 'ocean_foam_blend', {
      u_current: f.states[f.current], u_next: f.states[f.next], u_fraction: this.module.foamFraction(foamSettings, time),
    }, [f.output]);
  }

  // Records every cascade's maps (and foam) at `time` into `encoder`.
  encode(encoder, time, history = 'replay') {
    const tau = this.module.phaseTau(time);
    for (const { data, cascades } of this.oceans)
      for (const c of cascades) {
        if (c.foam) this.#foam(encoder, c, data.foam, time, data.choppiness, history);
        this.#cascade(encoder, c, tau, data.choppiness);
      }
  }

  // The texture of a manifest texture's "ocean" {ocean, cascade, map}.
  map(ref) {
    const c = this.oceans[ref.ocean]?.cascades[ref.cascade];
    const which = OCEAN_MAPS.indexOf(ref.map);
    if (!c || which < 0) throw new WebgpuOceanError(`an ocean texture names ocean ${ref.ocean} cascade ${ref.cascade} map ${ref.map}, which the simulation does not have`);
    // Map 3 (moments) is the third map of a filtered cascade; the water binds views of every level.
    const t = which === 2 ? c.foam?.output : which === 3 ? (c.filtered ? c.maps[2] : null) : c.maps[which];
    if (!t) throw new WebgpuOceanError(`ocean ${ref.ocean} cascade ${ref.cascade}: its ${ref.map} map is not computed (no shader samples it)`);
    return t;
  }
}
