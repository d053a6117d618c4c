// The shape of a compiled graph's manifest (docs/integration.md, "The manifest";
// codegen/manifest_read.cpp reads the same shape in C++), checked before the client uses any
// of it: a manifest is input, and one that is hand-edited, truncated or hostile fails here
// with a WaterGraphError naming the member at fault ("uniforms[2].builtin", also in the
// error's `field`), not later as a TypeError, a NaN uniform or a value silently taken.
// Only what the three.js client reads is checked in depth; the informative members
// ("nodes", "functions", "vulkan", "webgpu", ...) need only be of their kind.
import { WaterGraphError } from './watergraph-error.js';

// Tables keyed by names from the manifest have no prototype: "constructor" or "__proto__"
// is then no member of them.
const table = (entries) => Object.freeze(Object.assign(Object.create(null), entries));
const setOf = (names) => table(Object.fromEntries(names.map((n) => [n, true])));

export const MANIFEST_FORMAT = 1;

const TOP_LEVEL = setOf(['format', 'graph', 'description', 'preset', 'imports', 'targets', 'attributes', 'uniforms',
  'varyings', 'functions', 'textures', 'tessellation', 'resources', 'passes', 'pass_scales', 'nodes', 'vulkan', 'webgpu', 'color', 'oceans',
  'three']);
// Components of each uniform type the client uploads.
export const UNIFORM_COMPONENTS = table({ float: 1, int: 1, bool: 1, vec2: 2, vec3: 3, vec4: 4, mat3: 9, mat4: 16 });
// The builtins the client computes (watergraph-three.js BUILTIN_INITIAL and time_phase).
export const CLIENT_BUILTINS = setOf(['model', 'view_projection', 'view', 'projection', 'camera_position', 'time', 'time_phase',
  'viewport_size', 'camera_near_far', 'sun_direction']);
const STAGES = setOf(['vertex', 'fragment']);
const SCENE_RESOURCES = setOf(['scene_depth', 'scene_color', 'planar_reflection', 'refraction', 'environment', 'underwater']);
const SCALABLE_PASSES = setOf(['depth_prepass', 'planar_reflection', 'refraction', 'scene_color_copy', 'deferred_water']);
const TEXTURE_TYPES = setOf(['sampler2D', 'samplerCube']);
const SAMPLER_CHOICES = table({
  wrap: setOf(['repeat', 'clamp', 'mirror']),
  filter: setOf(['nearest', 'linear', 'mipmapped']),
  color_space: setOf(['linear', 'srgb']),
});
const OCEAN_MAP_NAMES = setOf(['displacement', 'slopes', 'foam', 'moments']);
const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

export const has = (object, key) => Object.prototype.hasOwnProperty.call(object, key);

function describe(x) {
  if (typeof x === 'string') return `'${x.length > 60 ? `${x.slice(0, 60)}...` : x}'`;
  if (Array.isArray(x)) return 'a list';
  if (x === null) return 'null';
  if (typeof x === 'object') return 'an object';
  return String(x);
}

// Checks `manifest` against the documented shape; returns it, or throws a WaterGraphError
// naming the field.
export function checkManifest(manifest) {
  const graph = manifest && typeof manifest === 'object' && typeof manifest.graph === 'string' ? manifest.graph : '?';
  const fail = (field, what, ...value) => {
    const got = value.length ? ` (got ${describe(value[0])})` : '';
    throw new WaterGraphError(`graph '${graph}': the manifest's ${field} ${what}${got}`, { field });
  };
  const isObject = (x) => x !== null && typeof x === 'object' && !Array.isArray(x);
  const object = (x, field) => {
    if (!isObject(x)) fail(field, 'must be an object', x);
    return x;
  };
  const list = (x, field) => {
    if (!Array.isArray(x)) fail(field, 'must be a list', x);
    return x;
  };
  const text = (x, field) => {
    if (typeof x !== 'string') fail(field, 'must be a string', x);
    return x;
  };
  const finite = (x, field) => {
    if (typeof x !== 'number' || !Number.isFinite(x)) fail(field, 'must be a finite number', x);
    return x;
  };
  const natural = (x, field) => {
    if (!Number.isInteger(x) || x < 0) fail(field, 'must be a whole number >= 0', x);
    return x;
  };
  const oneOf = (x, choices, field) => {
    if (typeof x !== 'string' || !choices[x]) fail(field, `must be one of ${Object.keys(choices).join(', ')}`, x);
    return x;
  };
  // Only the members the shape has: a misspelt or foreign one is named by its own path.
  const members = (x, allowed, field) => {
    for (const key of Object.keys(x))
      if (!allowed[key]) fail(field ? `${field}.${key}` : key, 'is not a member of the documented shape');
  };
  const identifier = (x, field) => {
    if (typeof x !== 'string' || !IDENTIFIER.test(x)) fail(field, 'must be an identifier ([A-Za-z_][A-Za-z0-9_]*)', x);
    return x;
  };
  const optional = (x, key, check, field) => {
    if (has(x, key)) check(x[key], `${field}.${key}`);
  };
  const plainFileName = (x, field) => {
    const file = text(x, field);
    if (file === '' || file === '.' || file === '..' || /[\/\\]/.test(file)) fail(field, 'must be a file name beside the manifest', file);
    return file;
  };

  if (!isObject(manifest)) throw new WaterGraphError(`the manifest must be a JSON object (got ${describe(manifest)})`, { field: '' });
  members(manifest, TOP_LEVEL, '');
  if (has(manifest, 'format') && manifest.format !== MANIFEST_FORMAT)
    fail('format', `must be ${MANIFEST_FORMAT}, the format this client reads`, manifest.format);
  for (const key of ['graph', 'description', 'preset']) if (has(manifest, key)) text(manifest[key], key);
  for (const key of ['imports', 'functions', 'varyings'])
    if (has(manifest, key)) list(manifest[key], key);
  for (const key of ['nodes', 'vulkan', 'webgpu', 'tessellation'])
    if (has(manifest, key)) object(manifest[key], key);

  // Pass names are strings; which ones the client can run it says itself, from the scene
  // description where there is one (a newer runtime may describe more).
  const passes = list(manifest.passes, 'passes');
  passes.forEach((p, i) => identifier(p, `passes[${i}]`));
  if (has(manifest, 'resources'))
    list(manifest.resources, 'resources').forEach((r, i) => oneOf(r, SCENE_RESOURCES, `resources[${i}]`));
  if (has(manifest, 'pass_scales')) {
    const scales = object(manifest.pass_scales, 'pass_scales');
    for (const pass of Object.keys(scales)) {
      const field = `pass_scales.${pass}`;
      if (!SCALABLE_PASSES[pass] || !passes.includes(pass)) fail(field, 'names no frame-sized scene pass that "passes" lists');
      const s = scales[pass];
      if (typeof s !== 'number' || !(s >= 0.25 && s < 1)) fail(field, 'must be a number >= 0.25 and < 1', s);
    }
  }

  const targets = object(manifest.targets ?? {}, 'targets');
  for (const name of Object.keys(targets)) {
    const files = object(targets[name], `targets.${name}`);
    for (const stage of Object.keys(files))
      if (stage !== 'entry_points') text(files[stage], `targets.${name}.${stage}`);
  }
  if (has(targets, 'es300')) for (const stage of ['vert', 'frag']) text(targets.es300[stage], `targets.es300.${stage}`);
  // "three": the es300 stages after their version line, which the client fetches (plain file
  // names beside the manifest), with the version they lack (watergraph-passes.js shaderForm).
  if (has(manifest, 'three')) {
    const three = object(manifest.three, 'three');
    members(three, STAGES, 'three');
    for (const stage of Object.keys(STAGES)) {
      const field = `three.${stage}`;
      const entry = object(three[stage], field);
      members(entry, setOf(['body_file', 'glsl_version']), field);
      plainFileName(entry.body_file, `${field}.body_file`);
      text(entry.glsl_version, `${field}.glsl_version`);
    }
  }

  if (has(manifest, 'attributes'))
    list(manifest.attributes, 'attributes').forEach((a, i) => {
      const field = `attributes[${i}]`;
      object(a, field);
      members(a, setOf(['name', 'type', 'location']), field);
      identifier(a.name, `${field}.name`);
      text(a.type, `${field}.type`);
      natural(a.location, `${field}.location`);
    });

  const uniforms = has(manifest, 'uniforms') ? list(manifest.uniforms, 'uniforms') : [];
  const names = new Set();
  const parameters = new Set();  // parameter names
  const unique = (name, field) => {
    if (names.has(name)) fail(field, 'names a uniform or texture twice', name);
    names.add(name);
  };
  uniforms.forEach((u, i) => {
    const field = `uniforms[${i}]`;
    object(u, field);
    identifier(u.name, `${field}.name`);
    unique(u.name, `${field}.name`);
    oneOf(u.type, UNIFORM_COMPONENTS, `${field}.type`);
    list(u.stages, `${field}.stages`).forEach((s, k) => oneOf(s, STAGES, `${field}.stages[${k}]`));
    if (has(u, 'parameter')) {
      members(u, setOf(['name', 'type', 'stages', 'parameter', 'default', 'min', 'max', 'hint', 'color_space', 'description']), field);
      const name = identifier(u.parameter, `${field}.parameter`);
      if (parameters.has(name)) fail(`${field}.parameter`, 'names a parameter another uniform holds', name);
      const d = u.default;
      const values = typeof d === 'boolean' ? [d] : Array.isArray(d) ? d : [d];
      if (values.some((x) => typeof x !== 'number' && typeof x !== 'boolean') ||
          values.some((x) => typeof x === 'number' && !Number.isFinite(x)))
        fail(`${field}.default`, 'must be a finite number, a boolean or a list of finite numbers', d);
      if (values.length !== UNIFORM_COMPONENTS[u.type]) fail(`${field}.default`, `must have ${UNIFORM_COMPONENTS[u.type]} value(s) for a ${u.type}`, d);
      optional(u, 'min', finite, field);
      optional(u, 'max', finite, field);
      if (has(u, 'min') && has(u, 'max') && !(u.min <= u.max)) fail(`${field}.min`, 'must not be above "max"', u.min);
      optional(u, 'hint', text, field);
      optional(u, 'description', text, field);
      if (has(u, 'color_space') && u.color_space !== 'srgb') fail(`${field}.color_space`, "must be 'srgb' or absent", u.color_space);
      parameters.add(name);
      return;
    }
    // A manifest written by the removed --derived-uniforms switch: its shader reads values
    // nothing computes any more.
    if (u.builtin === 'derived')
      fail(`${field}.builtin`, "is 'derived', a uniform watergraph no longer has: compile the graph again");
    const builtin = oneOf(u.builtin, CLIENT_BUILTINS, `${field}.builtin`);
    if (builtin === 'time_phase') {
      members(u, setOf(['name', 'type', 'stages', 'builtin', 'angular_frequency']), field);
      finite(u.angular_frequency, `${field}.angular_frequency`);
    } else {
      members(u, setOf(['name', 'type', 'stages', 'builtin']), field);
    }
  });

  if (has(manifest, 'textures'))
    list(manifest.textures, 'textures').forEach((t, i) => {
      const field = `textures[${i}]`;
      object(t, field);
      members(t, setOf(['name', 'type', 'binding', 'stages', 'source', 'file', 'resource', 'sampler', 'ocean']), field);
      identifier(t.name, `${field}.name`);
      unique(t.name, `${field}.name`);
      oneOf(t.type, TEXTURE_TYPES, `${field}.type`);
      natural(t.binding, `${field}.binding`);
      list(t.stages, `${field}.stages`).forEach((s, k) => oneOf(s, STAGES, `${field}.stages[${k}]`));
      if ((has(t, 'source') ? 1 : 0) + (has(t, 'resource') ? 1 : 0) + (has(t, 'ocean') ? 1 : 0) !== 1)
        fail(field, 'must have exactly one of "source", "resource" and "ocean"');
      if (has(t, 'ocean')) {
        // A map of the ocean simulation (watergraph-ocean.js); "oceans" is checked below.
        if (has(t, 'sampler') || has(t, 'file')) fail(field, 'is an ocean map ("ocean"), which has no "sampler" or "file"');
        if (t.type !== 'sampler2D') fail(`${field}.type`, 'must be sampler2D for an ocean map', t.type);
        const ref = object(t.ocean, `${field}.ocean`);
        members(ref, setOf(['ocean', 'cascade', 'map']), `${field}.ocean`);
        natural(ref.ocean, `${field}.ocean.ocean`);
        natural(ref.cascade, `${field}.ocean.cascade`);
        oneOf(ref.map, OCEAN_MAP_NAMES, `${field}.ocean.map`);
      } else if (has(t, 'source')) {
        text(t.source, `${field}.source`);
        // The PNG `compile --textures` wrote: a plain file name beside the manifest.
        plainFileName(t.file, `${field}.file`);
        if (has(t, 'sampler')) {
          const s = object(t.sampler, `${field}.sampler`);
          members(s, SAMPLER_CHOICES, `${field}.sampler`);
          for (const key of Object.keys(SAMPLER_CHOICES)) oneOf(s[key], SAMPLER_CHOICES[key], `${field}.sampler.${key}`);
        }
      } else {
        if (has(t, 'sampler') || has(t, 'file')) fail(field, 'is a scene texture ("resource"), which has no "sampler" or "file"');
        oneOf(t.resource, SCENE_RESOURCES, `${field}.resource`);
      }
    });

  // The spectral oceans (watergraph-ocean.js): each names the module `compile` wrote beside
  // the manifest (one for all of them), which the client imports; the options are the
  // runtime's (the module holds what the client needs of them).
  const oceans = has(manifest, 'oceans') ? list(manifest.oceans, 'oceans') : [];
  if ((oceans.length > 0) !== passes.includes('ocean_simulation'))
    fail(oceans.length ? 'passes' : 'oceans', oceans.length ? 'must list ocean_simulation for the manifest\'s "oceans"'
      : 'must describe the oceans of the ocean_simulation pass "passes" lists');
  oceans.forEach((o, i) => {
    const field = `oceans[${i}]`;
    object(o, field);
    members(o, setOf(['filtered', 'module', 'node', 'options']), field);
    text(o.node, `${field}.node`);
    object(o.options, `${field}.options`);
    if (!has(o, 'module')) fail(`${field}.module`, 'is missing: compile the graph for es300, which writes the ocean module the client simulates it from');
    const module = text(o.module, `${field}.module`);
    if (!/^[^\/\\]+\.js$/.test(module) || module === '.js') fail(`${field}.module`, 'must be a .js file name beside the manifest', module);
    if (module !== oceans[0].module) fail(`${field}.module`, 'must be the module the first ocean names', module);
    // Whether a shader reads its moments maps (the compiler decides it; watergraph-ocean-plan.js).
    if (!has(o, 'filtered')) fail(`${field}.filtered`, 'is missing: compile the graph again, which writes whether the ocean is filtered');
    if (typeof o.filtered !== 'boolean') fail(`${field}.filtered`, 'must be true or false', o.filtered);
  });
  (manifest.textures ?? []).forEach((t, i) => {
    if (!has(t, 'ocean')) return;
    const ref = t.ocean, field = `textures[${i}].ocean`;
    if (!Number.isInteger(ref.ocean) || ref.ocean < 0 || ref.ocean >= oceans.length) fail(`${field}.ocean`, 'must index the manifest\'s "oceans"', ref.ocean);
  });
  // "filtered" and the moments maps the textures read are one decision of the compiler's.
  oceans.forEach((o, i) => {
    const moments = (manifest.textures ?? []).some((t) => has(t, 'ocean') && t.ocean.ocean === i && t.ocean.map === 'moments');
    if (moments !== o.filtered)
      fail(`oceans[${i}].filtered`, moments ? 'must be true: a texture reads the ocean\'s moments map' : 'must be false: no texture reads the ocean\'s moments map', o.filtered);
  });

  if (has(manifest, 'color')) object(manifest.color, 'color');  // its members: manifestView (watergraph-output.js)
  return manifest;
}
