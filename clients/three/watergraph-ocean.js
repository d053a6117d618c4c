// The spectral ocean's simulation pass (a manifest's "ocean_simulation") in WebGL 2 with
// EXT_color_buffer_float: the runtime's passes (runtime/ocean_simulation.cpp,
// runtime/ocean_gpu_cascade.cpp, runtime/ocean_gpu_foam.cpp) in the same order, with the
// runtime's own shaders from the scene description (`watergraph scene`: ocean_evolve,
// ocean_stockham, ocean_pack, ocean_foam_step, ...) and what only the compiler knows from the
// graph's ocean module (`watergraph compile` writes <graph>.ocean.js for a web target,
// codegen/ocean_module_js.h): each cascade's h0 and frequency indices, the twiddles, the
// 32-bit time phase, the foam's constants and clock. This file holds no ocean maths, only
// the passes' plumbing: which textures, which targets, in which order. A filtered cascade's
// pyramids (ocean_pack_filtered, ocean_downsample) are drawn by watergraph-ocean-pyramid.js.
import * as THREE from 'three';
import { WaterGraphError } from './watergraph-error.js';
import { fullScreenTriangle, runtimeMaterial } from './watergraph-passes.js';
import { OceanPyramid, PyramidPrograms } from './watergraph-ocean-pyramid.js';
import { cascadeMaps, cascadePasses, OCEAN_MAPS } from './watergraph-ocean-plan.js';

// The plan's names, from the module both web clients share.
export { cascadePasses, OCEAN_MAPS };

// A float texture read by texelFetch (nearest, no mipmaps), N x N unless given.
function dataTexture(data, width, height, format, type, internalFormat = null) {
  const t = new THREE.DataTexture(data, width, height, format, type);
  if (internalFormat) t.internalFormat = internalFormat;
  t.minFilter = t.magFilter = THREE.NearestFilter;
  t.generateMipmaps = false;
  t.needsUpdate = true;
  return t;
}

// A render target of `count` float attachments (RGBA32F, or R32F for foam), nearest.
function floatTarget(n, count, format = THREE.RGBAFormat) {
  return new THREE.WebGLRenderTarget(n, n, {
    count, type: THREE.FloatType, format, depthBuffer: false, stencilBuffer: false,
    minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false,
  });
}

// The passes' programs: one material per shader of the description, its uniforms set
// before each draw.
class OceanPasses {
  constructor(description) {
    this.description = description;
    this.materials = Object.create(null);
    this.mesh = new THREE.Mesh(fullScreenTriangle());
    this.mesh.frustumCulled = false;
    this.scene = new THREE.Scene().add(this.mesh);
    this.camera = new THREE.Camera();
  }

  material(name) {
    if (!this.materials[name]) {
      if (!this.description.three?.shaders?.[name])
        throw new WaterGraphError(`the scene description has no shader '${name}' (write it with a watergraph that simulates oceans)`);
      this.materials[name] = runtimeMaterial(this.description, 'fullscreen_vertex', name, {},
        { depthTest: false, depthWrite: false, blending: THREE.NoBlending });
    }
    return this.materials[name];
  }

  // One full-screen draw of shader `name` with `uniforms` into `target`.
  draw(renderer, name, uniforms, target) {
    const material = this.material(name);
    for (const key of Object.keys(uniforms)) {
      if (!material.uniforms[key]) material.uniforms[key] = { value: uniforms[key] };
      else material.uniforms[key].value = uniforms[key];
    }
    material.uniformsNeedUpdate = true;  // three.js skips the upload when the same material drew last
    this.mesh.material = material;
    renderer.setRenderTarget(target);
    renderer.render(this.scene, this.camera);
  }

  dispose() {
    for (const m of Object.values(this.materials)) m.dispose();
    this.mesh.geometry.dispose();
  }
}

// One cascade (runtime/ocean_gpu_cascade.h): the evolution, 2 log2 N Stockham stages, the
// packing; with `jacobian`, the foam's Jacobian fields alone into targets of their own.
class OceanCascade {
  constructor(data, c, packed, twiddle, { slopes, filtered }, jacobian) {
    const n = data.sizes[c];  // the cascade's own N (cascade_sizes)
    this.n = n;
    this.dk = data.dk[c];
    this.filtered = filtered;
    this.slopes = slopes;
    this.plan = cascadePasses(n, { slopes, filtered });
    this.twiddle = twiddle;
    this.h0 = dataTexture(packed.h0, n, n, THREE.RGBAFormat, THREE.FloatType);
    this.frequency = dataTexture(packed.frequency, n, n, THREE.RedIntegerFormat, THREE.UnsignedIntType, 'R32UI');
    const fields = this.slopes ? 2 : 1;
    this.spectra = [floatTarget(n, fields), floatTarget(n, fields)];
    // A filtered cascade's maps are the pyramid's (raw WebGL textures with every level).
    this.pyramid = filtered ? new OceanPyramid(n) : null;
    this.maps = filtered ? null : floatTarget(n, fields);
    this.jacobianTargets = jacobian ? [floatTarget(n, 1), floatTarget(n, 1)] : null;
  }

  #evolve(renderer, passes, shader, tau, target) {
    passes.draw(renderer, shader, { u_h0: this.h0, u_frequency: this.frequency, u_tau: tau, u_dk: this.dk, u_n: this.n }, target);
  }

  // The Stockham stages from targets[0] ping-ponging; returns the index holding the result.
  #transform(renderer, passes, shader, both, targets) {
    let current = 0;
    for (let vertical = 0; vertical < 2; ++vertical)
      for (let ns = 1; ns < this.n; ns *= 2) {
        const source = targets[current];
        passes.draw(renderer, shader, {
          u_a: source.textures[0], u_b: both ? source.textures[1] : null, u_twiddle: this.twiddle,
          u_n: this.n, u_ns: ns, u_vertical: vertical,
        }, targets[1 - current]);
        current = 1 - current;
      }
    return current;
  }

  // The passes of this.plan (cascadePasses) in order.
  update(renderer, passes, tau, choppiness, pyramidPrograms) {
    let current = 0;  // the spectra target holding the last result
    for (const p of this.plan) {
      const result = this.spectra[current];
      if (p.shader.startsWith('ocean_evolve')) {
        this.#evolve(renderer, passes, p.shader, tau, this.spectra[0]);
        current = 0;
      } else if (p.shader.startsWith('ocean_stockham')) {
        passes.draw(renderer, p.shader, {
          u_a: result.textures[0], u_b: this.slopes ? result.textures[1] : null, u_twiddle: this.twiddle,
          u_n: this.n, u_ns: p.ns, u_vertical: p.vertical,
        }, this.spectra[1 - current]);
        current = 1 - current;
      } else if (p.shader === 'ocean_pack_filtered') {
        // The pack and every downsample after it, in one stretch of raw WebGL.
        this.pyramid.update(renderer, pyramidPrograms, result.textures[0], result.textures[1], choppiness);
      } else if (p.shader !== 'ocean_downsample') {
        passes.draw(renderer, p.shader,
          { u_a: result.textures[0], u_b: this.slopes ? result.textures[1] : null, u_lambda: choppiness }, this.maps);
      }
    }
  }

  // (dh/dz, dDx/dx, dDz/dz, dDx/dz) at phase `tau`, without the choppiness: a texture valid
  // until the next call.
  jacobianFields(renderer, passes, tau) {
    this.#evolve(renderer, passes, 'ocean_evolve_jacobian', tau, this.jacobianTargets[0]);
    const current = this.#transform(renderer, passes, 'ocean_stockham_single', false, this.jacobianTargets);
    return this.jacobianTargets[current].texture;
  }

  // Map 0 (displacement), 1 (slopes) or 3 (moments, filtered cascades alone).
  map(which) {
    if (this.pyramid) return this.pyramid.textures[which === 3 ? 2 : which];
    return this.maps.textures[which];
  }

  dispose() {
    for (const t of [this.h0, this.frequency]) t.dispose();
    for (const t of [...this.spectra, ...(this.maps ? [this.maps] : []), ...(this.jacobianTargets ?? [])]) t.dispose();
    this.pyramid?.dispose();
  }
}

// One cascade's persistent foam (runtime/ocean_gpu_foam.h): a ring of three R32F states
// holding f_n and f_(n+1), and the map at the frame's time between them.
class OceanFoam {
  constructor(n, foam, module) {
    this.foam = foam;
    this.module = module;
    this.states = [floatTarget(n, 1, THREE.RedFormat), floatTarget(n, 1, THREE.RedFormat), floatTarget(n, 1, THREE.RedFormat)];
    this.output = floatTarget(n, 1, THREE.RedFormat);
    this.current = 0;
    this.next = 1;
    this.valid = false;
    this.at = 0;
    this.lastSteps = 0;
  }

  #step(renderer, passes, m, choppiness, cascade) {
    const fields = cascade.jacobianFields(renderer, passes, this.module.phaseTau(m * this.foam.step));
    const written = 3 - this.current - this.next;
    passes.draw(renderer, 'ocean_foam_step', {
      u_fields: fields, u_previous: this.states[this.next].texture, u_lambda: choppiness,
      u_keep: this.foam.keep, u_gain: this.foam.gain, u_threshold: this.foam.threshold,
    }, this.states[written]);
    this.current = this.next;
    this.next = written;
    ++this.lastSteps;
  }

  // As OceanGpuFoam::update: continued from the held steps when `history` is 'continue' and
  // they are at most K steps back (or hold this very step), else replayed from no foam.
  update(renderer, passes, time, choppiness, cascade, history) {
    const n = this.module.foamStepIndex(this.foam, time), k = this.foam.historySteps;
    this.lastSteps = 0;
    const continues = this.valid && n >= this.at && (n === this.at || (history === 'continue' && n - this.at <= k));
    if (continues) {
      for (let m = this.at + 2; m <= n + 1; ++m) this.#step(renderer, passes, m, choppiness, cascade);
    } else {
      renderer.setRenderTarget(this.states[this.next]);
      renderer.setClearColor(0x000000, 0);
      renderer.clear(true, false, false);
      for (let m = n - k + 1; m <= n + 1; ++m) this.#step(renderer, passes, m, choppiness, cascade);
    }
    this.valid = true;
    this.at = n;
    passes.draw(renderer, 'ocean_foam_blend', {
      u_current: this.states[this.current].texture, u_next: this.states[this.next].texture,
      u_fraction: this.module.foamFraction(this.foam, time),
    }, this.output);
  }

  dispose() {
    for (const t of [...this.states, this.output]) t.dispose();
  }
}

// Every ocean of a manifest, from its ocean module (the <graph>.ocean.js the manifest's
// "oceans" name) and a scene description's shaders. Only the maps a shader samples are
// computed: a cascade without a sampled slope map transforms its displacement alone, and
// foam runs only where a shader samples it.
export class OceanSimulation {
  constructor(manifest, module, description) {
    const graph = manifest.graph;
    if (!module || !Array.isArray(module.oceans))
      throw new WaterGraphError(`graph '${graph}' has a spectral ocean but no ocean module was given (the file its "oceans" entries name as "module", written by \`watergraph compile --target es300\`)`);
    if (module.oceans.length !== manifest.oceans.length)
      throw new WaterGraphError(`graph '${graph}': its ocean module describes ${module.oceans.length} ocean(s), the manifest ${manifest.oceans.length}: compile the graph again`);
    this.module = module;
    this.passes = new OceanPasses(description);
    this.pyramidPrograms = new PyramidPrograms(description);
    const twiddles = new Map();  // one texture per resolution
    this.oceans = module.oceans.map((data, o) => {
      if (data.node !== manifest.oceans[o].node)
        throw new WaterGraphError(`graph '${graph}': its ocean module's ocean ${o} is node '${data.node}', the manifest's '${manifest.oceans[o].node}': compile the graph again`);
      const packed = data.cascades();
      const cascades = [], foam = [];
      data.tileLengths.forEach((_, c) => {
        const n = data.sizes[c];
        if (!twiddles.has(n)) twiddles.set(n, dataTexture(module.twiddles(n), n / 2, 1, THREE.RGFormat, THREE.FloatType));
        // The manifest's "filtered" (the compiler's) makes every cascade of the ocean keep pyramids.
        const maps = cascadeMaps(manifest, o, c);
        if (maps.foam && c >= data.foam.cascades)
          throw new WaterGraphError(`graph '${graph}': a texture reads the foam of ocean ${data.node} cascade ${c}, which its foam_cascades gives no foam`);
        cascades.push(new OceanCascade(data, c, packed[c], twiddles.get(n), maps, maps.foam));
        foam.push(maps.foam ? new OceanFoam(n, data.foam, module) : null);
      });
      return { data, cascades, foam };
    });
    this.twiddles = [...twiddles.values()];
    this.heldAt = null;  // [time, history] the maps hold
    this.updatesRun = 0;
  }

  // The texture of a manifest texture's "ocean" {ocean, cascade, map}.
  map(ref) {
    const ocean = this.oceans[ref.ocean], cascade = ocean?.cascades[ref.cascade];
    if (!cascade) throw new WaterGraphError(`an ocean texture names ocean ${ref.ocean} cascade ${ref.cascade}, which the manifest's "oceans" does not describe`);
    const which = OCEAN_MAPS.indexOf(ref.map);
    if (which < 0) throw new WaterGraphError(`an ocean texture names map '${ref.map}' (the maps are ${OCEAN_MAPS.join(', ')})`);
    if (which === 2) return ocean.foam[ref.cascade].output.texture;
    if (which === 3 && !cascade.filtered)
      throw new WaterGraphError(`ocean ${ref.ocean} cascade ${ref.cascade}: its moments map is not computed (no shader samples it)`);
    return cascade.map(which);
  }

  // Every cascade's maps (and foam) at `time` (s). history: 'replay' (a still frame: the
  // foam of its time alone, as the runtime's render) or 'continue' (an animation: from the
  // previous frame's foam steps). Nothing runs when the maps already hold that time.
  update(renderer, time, history = 'replay') {
    if (history !== 'replay' && history !== 'continue')
      throw new WaterGraphError(`the ocean's foam history must be 'replay' or 'continue' (got ${JSON.stringify(history)})`);
    if (this.heldAt && this.heldAt[0] === time && this.heldAt[1] === history) return false;
    this.heldAt = null;
    ++this.updatesRun;
    const saved = { target: renderer.getRenderTarget(), autoClear: renderer.autoClear,
      clear: renderer.getClearColor(new THREE.Color()), alpha: renderer.getClearAlpha() };
    renderer.autoClear = false;
    try {
      const tau = this.module.phaseTau(time);
      for (const { data, cascades, foam } of this.oceans)
        cascades.forEach((cascade, c) => {
          // The foam first: its steps use the cascade's Jacobian targets, update its spectra.
          if (foam[c]) foam[c].update(renderer, this.passes, time, data.choppiness, cascade, history);
          cascade.update(renderer, this.passes, tau, data.choppiness, this.pyramidPrograms);
        });
    } finally {
      renderer.autoClear = saved.autoClear;
      renderer.setClearColor(saved.clear, saved.alpha);
      renderer.setRenderTarget(saved.target);
    }
    this.heldAt = [time, history];
    return true;
  }

  dispose() {
    for (const { cascades, foam } of this.oceans) {
      cascades.forEach((c) => c.dispose());
      foam.forEach((f) => f?.dispose());
    }
    this.twiddles.forEach((t) => t.dispose());
    this.passes.dispose();
    this.pyramidPrograms.dispose();
  }
}
