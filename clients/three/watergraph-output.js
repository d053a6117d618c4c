// The output transform, the client's last pass: the frame's linear, scene-referred radiance
// (an RGBA16F target) through exposure, a tone mapper and the sRGB curve into the canvas or
// the caller's target, as runtime/output_transform.cpp does it. The maths is the runtime's
// own ES 3.00 shader from the scene description (`three.shaders.output_transform_fragment`),
// drawn with its full-screen triangle; three.js adds no tone mapping or colour-space step.
// Also the checks of the view a manifest states (its "color" member) and of the render
// options that override it.
import * as THREE from 'three';
import { WaterGraphError, runtimeMaterial, fullScreenTriangle } from './watergraph-passes.js';

// The tone mappers this client knows, in the runtime's order (core/view_transform.h); the
// shader takes the index of the name in the description's "color.tone_mappers".
export const TONE_MAPPERS = ['none', 'aces', 'agx', 'neutral'];
// Exposure in EV (stops), as the runtime bounds it.
export const EXPOSURE_RANGE = [-20, 20];

// The view before any option: no tone mapping (clamp), 0 EV, as the runtime's default.
export const DEFAULT_VIEW = Object.freeze({ toneMapping: 'none', exposure: 0 });

function describe(x) {
  return typeof x === 'string' ? `'${x}'` : JSON.stringify(x) ?? String(x);
}

function checkToneMapping(name, what) {
  if (!TONE_MAPPERS.includes(name))
    throw new WaterGraphError(`${what} must be one of ${TONE_MAPPERS.join(', ')} (got ${describe(name)})`);
  return name;
}

function checkExposure(ev, what) {
  if (typeof ev !== 'number' || !Number.isFinite(ev) || ev < EXPOSURE_RANGE[0] || ev > EXPOSURE_RANGE[1])
    throw new WaterGraphError(`${what} must be a finite number of EV in [${EXPOSURE_RANGE.join(', ')}] (got ${describe(ev)})`);
  return ev;
}

function onlyMembers(object, allowed, what) {
  for (const key of Object.keys(object))
    if (!allowed.includes(key)) throw new WaterGraphError(`${what} has an unknown member "${key}"`);
}

// The manifest's "color" member: the contract (a linear bt709 frame, sRGB output) and the
// graph's preferred view, as { toneMapping, exposure }. A manifest without one (written
// before it existed) has the default view. Anything else the runtime would refuse is
// refused here too.
export function manifestView(manifest) {
  const c = manifest.color;
  if (c === undefined) return { ...DEFAULT_VIEW };
  const what = `graph '${manifest.graph}': the manifest's "color"`;
  if (!c || typeof c !== 'object' || Array.isArray(c)) throw new WaterGraphError(`${what} is not an object`);
  onlyMembers(c, ['frame', 'primaries', 'view'], what);
  if (c.frame !== 'linear') throw new WaterGraphError(`${what} has a "frame" other than "linear" (got ${describe(c.frame)})`);
  if (c.primaries !== 'bt709') throw new WaterGraphError(`${what} has "primaries" other than "bt709" (got ${describe(c.primaries)})`);
  const v = c.view;
  if (!v || typeof v !== 'object' || Array.isArray(v)) throw new WaterGraphError(`${what} has no "view" object`);
  onlyMembers(v, ['exposure', 'output', 'tonemap'], `${what}'s view`);
  if (v.output !== 'srgb') throw new WaterGraphError(`${what}'s view has an "output" other than "srgb" (got ${describe(v.output)})`);
  return {
    toneMapping: checkToneMapping(v.tonemap, `${what}'s view "tonemap"`),
    exposure: checkExposure(v.exposure, `${what}'s view "exposure"`),
  };
}

// The view one render() uses: the render options `toneMapping` and `exposure` (EV) over the
// graph's own view; a bad option is a WaterGraphError naming it.
export function renderView(graphView, options = {}) {
  const view = { ...graphView };
  if (options.toneMapping !== undefined) view.toneMapping = checkToneMapping(options.toneMapping, 'the render option toneMapping');
  if (options.exposure !== undefined) view.exposure = checkExposure(options.exposure, 'the render option exposure');
  return view;
}

// Checks a scene description's "color" member: the formats and tone mappers this client
// implements the passes for.
export function checkColorDescription(description) {
  const c = description.color;
  const what = 'the scene description\'s "color"';
  if (!c || typeof c !== 'object') throw new WaterGraphError(`${what} is missing`);
  if (c.frame_format !== 'rgba16f') throw new WaterGraphError(`${what} has frame_format ${describe(c.frame_format)}; this client knows rgba16f`);
  if (c.display_format !== 'rgba8') throw new WaterGraphError(`${what} has display_format ${describe(c.display_format)}; this client knows rgba8`);
  if (!Array.isArray(c.tone_mappers) || TONE_MAPPERS.some((t) => !c.tone_mappers.includes(t)))
    throw new WaterGraphError(`${what} lacks some of the tone mappers ${TONE_MAPPERS.join(', ')}`);
  const r = c.exposure_range;
  if (!Array.isArray(r) || r[0] !== EXPOSURE_RANGE[0] || r[1] !== EXPOSURE_RANGE[1])
    throw new WaterGraphError(`${what} has an exposure_range other than [${EXPOSURE_RANGE.join(', ')}]`);
  for (const s of ['fullscreen_vertex', 'output_transform_fragment'])
    if (!description.three?.shaders?.[s]) throw new WaterGraphError(`the scene description has no shader "${s}" ("three".shaders)`);
}

// The output pass: one full-screen triangle running the runtime's output transform shader,
// reading the frame texel for texel (texelFetch at gl_FragCoord), so the target it writes
// must be the frame's size.
export class OutputTransform {
  constructor(description) {
    checkColorDescription(description);
    this.toneMappers = description.color.tone_mappers;
    this.uniforms = {
      u_frame: { value: null },
      u_exposure_scale: { value: 1 },
      u_tone_mapper: { value: 0 },
    };
    this.material = runtimeMaterial(description, 'fullscreen_vertex', 'output_transform_fragment', this.uniforms, {
      depthTest: false, depthWrite: false, blending: THREE.NoBlending,
    });
    this.material.name = 'watergraph output transform';
    this.mesh = new THREE.Mesh(fullScreenTriangle(), this.material);
    this.mesh.frustumCulled = false;
    this.scene = new THREE.Scene().add(this.mesh);
    this.camera = new THREE.Camera();  // the vertex shader ignores it
  }

  // The uniforms of a view, as runtime/output_transform.cpp's outputTransformUniforms.
  setView({ toneMapping, exposure }) {
    this.uniforms.u_exposure_scale.value = Math.pow(2, exposure);
    this.uniforms.u_tone_mapper.value = this.toneMappers.indexOf(toneMapping);
  }

  // `frame` (a render target holding linear radiance) through `view` into `output` (a render
  // target of the frame's size, or null: the canvas). three.js's own tone mapping and output
  // colour space are set aside for the draw (a RawShaderMaterial gets neither, and with
  // NoToneMapping three.js draws to the canvas directly, not through its own output buffer).
  render(renderer, frame, output, view) {
    this.setView(view);
    this.uniforms.u_frame.value = frame.texture;
    const saved = { toneMapping: renderer.toneMapping, colorSpace: renderer.outputColorSpace, autoClear: renderer.autoClear };
    renderer.toneMapping = THREE.NoToneMapping;
    renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
    renderer.autoClear = false;  // every pixel is written
    try {
      renderer.setRenderTarget(output);
      renderer.render(this.scene, this.camera);
    } finally {
      renderer.toneMapping = saved.toneMapping;
      renderer.outputColorSpace = saved.colorSpace;
      renderer.autoClear = saved.autoClear;
    }
  }

  dispose() {
    this.material.dispose();
    this.mesh.geometry.dispose();
  }
}
