// Derived uniforms in the browser: a value the compiler took out of the shader because it is
// the same for every pixel of a draw (the manifest's uniforms with "builtin": "derived"). Its
// "derived" entry is a small program in watergraph's node vocabulary; compileDerived turns it
// into a JavaScript function once, without eval, and the client calls it every draw, in
// double precision, as the runtime does with its CPU backend. Each node type below follows
// that backend's formula (the same guards and constants; a NaN goes where the C++ reference
// sends it), and watergraph's tests hold the two to each other for every type.

export class DerivedProgramError extends Error {}

// Tables keyed by names a manifest gives (node types, comparisons, swizzle letters) have no
// prototype: an op of type "constructor" or a comparison "__proto__" is no member of them.
const table = (entries) => Object.freeze(Object.assign(Object.create(null), entries));
const own = (object, key) => Object.prototype.hasOwnProperty.call(object, key);
const isObject = (x) => x !== null && typeof x === 'object' && !Array.isArray(x);
const listOf = (x) => (Array.isArray(x) ? x : []);

// std::min / std::max, whose comparisons decide where a NaN goes (Math.min would return NaN).
const min = (a, b) => (b < a ? b : a);
const max = (a, b) => (a < b ? b : a);
const clamp = (x, lo, hi) => min(max(x, lo), hi);
const mix = (a, b, t) => a * (1 - t) + b * t;
const FLT_MIN = 1.1754943508222875e-38;  // 2^-126: floor of log's and inversesqrt's argument

function smoothstep(e0, e1, x) {
  if (e0 === e1) return x < e0 ? 0 : 1;
  const t = clamp((x - e0) / (e1 - e0), 0, 1);
  return t * t * (3 - 2 * t);
}
function safePow(x, y) {
  if (x > 0) return Math.pow(2, min(y * Math.log2(x), 127));
  return y > 0 ? 0 : 1;
}
function safeMod(x, y) {
  const q = x / y;
  return Math.abs(q) <= 1e38 ? x - y * Math.floor(q) : 0;
}
function safeTan(x) {
  const c = Math.cos(x);
  const d = c < 0 ? min(c, -1e-30) : max(c, 1e-30);
  return Math.sin(x) / d;
}
function safeAtan2(y, x) {
  if (y === 0) return x < 0 ? Math.PI : 0;
  return Math.atan2(y, x);
}
// The sRGB transfer function (IEC 61966-2-1) decoding one colour component to linear, as
// watergraph's srgb_to_linear node: mirrored for negative values, continued past 1 (capped
// at 2^127), and [0, 1] kept within [0, 1].
function srgbToLinear(c) {
  const a = Math.abs(c);
  let v = a <= 0.04045 ? a / 12.92 : Math.pow((a + 0.055) / 1.055, 2.4);
  v = min(v, a <= 1 ? 1 : 1.7014118346046923e38);
  return c < 0 ? -v : v;
}
// GLSL's roundEven (C's nearbyint in the default rounding mode): halves to the even integer.
function roundEven(x) {
  const r = Math.round(x);
  return Math.abs(x % 1) === 0.5 ? 2 * Math.round(x / 2) : r;
}

// Component-wise node types: the formula over one component of each input.
const COMPONENT_WISE = table({
  add: (a, b) => a + b,
  sub: (a, b) => a - b,
  mul: (a, b) => a * b,
  div: (a, b) => a / b,
  mix,
  clamp,
  saturate: (x) => clamp(x, 0, 1),
  smoothstep,
  pow: safePow,
  sin: Math.sin,
  cos: Math.cos,
  tan: safeTan,
  asin: (x) => Math.asin(clamp(x, -1, 1)),
  acos: (x) => Math.acos(clamp(x, -1, 1)),
  atan: Math.atan,
  atan2: safeAtan2,
  sinh: (x) => Math.sinh(clamp(x, -88, 88)),
  cosh: (x) => Math.cosh(clamp(x, -88, 88)),
  tanh: (x) => Math.tanh(clamp(x, -10, 10)),
  abs: Math.abs,
  min,
  max,
  fract: (x) => x - Math.floor(x),
  floor: Math.floor,
  ceil: Math.ceil,
  round: roundEven,
  trunc: Math.trunc,
  mod: safeMod,
  step: (edge, x) => (x < edge ? 0 : 1),
  sign: (x) => (x > 0 ? 1 : x < 0 ? -1 : 0),
  negate: (x) => -x,
  one_minus: (x) => 1 - x,
  exp: (x) => Math.exp(min(x, 88)),
  exp2: (x) => Math.pow(2, min(x, 127)),
  log: (x) => Math.log(max(x, FLT_MIN)),
  log2: (x) => Math.log2(max(x, FLT_MIN)),
  sqrt: (x) => Math.sqrt(max(x, 0)),
  inversesqrt: (x) => 1 / Math.sqrt(max(x, FLT_MIN)),
  inverse_mix: (a, b, x) => (b === a ? 0 : (x - a) / (b - a)),
});

const COMPARISONS = table({
  less: (a, b) => a < b,
  less_equal: (a, b) => a <= b,
  greater: (a, b) => a > b,
  greater_equal: (a, b) => a >= b,
  equal: (a, b) => a === b,
  not_equal: (a, b) => a !== b,
});

const COMPONENTS = table({ float: 1, vec2: 2, vec3: 3, vec4: 4, mat4: 16 });
const SWIZZLE = table({ x: 0, y: 1, z: 2, w: 3, r: 0, g: 1, b: 2, a: 3 });
// The per-draw builtins a program may read, by the names the manifest uses.
export const DERIVED_BUILTINS = ['time', 'camera_position', 'camera_near_far', 'view', 'projection', 'sun_direction'];

const at = (v, i) => v[v.length === 1 ? 0 : i];
const dot = (a, b) => {
  let s = 0;
  for (let i = 0; i < a.length; ++i) s += a[i] * b[i];
  return s;
};

// The inputs of each node type that is not component-wise (those take as many as their
// formula's parameters): what the compiler writes, one per port of the type.
const ARITY = table({
  time: 0, camera_position: 0, sun_direction: 0, camera_forward: 0, near_far_ratio: 1,
  compare: 2, select: 4, dot: 2, length: 1, distance: 2, normalize: 1, cross: 2, swizzle: 1,
  split: 1, combine: 4, remap: 5, srgb_to_linear: 1,
});
const arityOf = (type) => ARITY[type] ?? COMPONENT_WISE[type]?.length;

// Whether `port` names an output of `op` that has a value (split's missing components do not).
const isPort = (op, port) => Number.isInteger(port) && port >= 0 && COMPONENTS[listOf(op.output_types)[port]] !== undefined;

function componentsOf(type, what) {
  const n = COMPONENTS[type];
  if (!n) throw new DerivedProgramError(`${what}: unknown type '${type}'`);
  return n;
}

// The function computing one op's outputs (an array per output port) from its inputs'
// values, or an error for a node type outside the vocabulary.
function opFunction(op, what) {
  const type = op.type;
  const outputs = listOf(op.output_types).map((t) => (t === 'invalid' ? 0 : componentsOf(t, what)));
  const n = outputs[0] ?? 0;
  const f = COMPONENT_WISE[type];
  if (f) {
    return (xs) => {
      const r = new Array(n);
      for (let i = 0; i < n; ++i) r[i] = f(...xs.map((x) => at(x, i)));
      return [r];
    };
  }
  const options = isObject(op.options) ? op.options : {};
  switch (type) {
    case 'time':
    case 'camera_position':
    case 'sun_direction':
      return (xs, draw) => [typeof draw[type] === 'number' ? [draw[type]] : Array.from(draw[type])];
    case 'camera_forward':
      // -(row 2) of the column-major view matrix; the zero vector for a degenerate one.
      return (xs, draw) => {
        const f = [-draw.view[2], -draw.view[6], -draw.view[10]];
        const l2 = dot(f, f);
        if (l2 < 0.5) return [[0, 0, 0]];
        const k = 1 / Math.sqrt(max(l2, 1e-30));
        return [f.map((x) => x * k)];
      };
    case 'near_far_ratio':
      return ([nf]) => {
        const n = max(nf[0], 1e-6);
        return [[n], [n / max(nf[1], n)]];
      };
    case 'compare':
    case 'select': {
      const holds = COMPARISONS[own(options, 'op') ? options.op : 'less'];
      if (!holds) throw new DerivedProgramError(`${what}: unknown comparison '${options.op}'`);
      return (xs) => {
        const r = new Array(n);
        for (let i = 0; i < n; ++i) {
          const h = holds(at(xs[0], i), at(xs[1], i));
          r[i] = type === 'compare' ? (h ? 1 : 0) : h ? at(xs[2], i) : at(xs[3], i);
        }
        return [r];
      };
    }
    case 'dot':
      return ([a, b]) => [[dot(a, b)]];
    case 'length':
      return ([a]) => [[Math.sqrt(dot(a, a))]];
    case 'distance':
      return ([a, b]) => {
        const m = Math.max(a.length, b.length);
        const d = [];
        for (let i = 0; i < m; ++i) d.push(at(a, i) - at(b, i));
        return [[Math.sqrt(dot(d, d))]];
      };
    case 'normalize':
      return ([a]) => {
        const k = 1 / Math.sqrt(max(dot(a, a), 1e-30));
        return [a.map((x) => x * k)];
      };
    case 'cross':
      return ([a, b]) => [[a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]];
    case 'swizzle': {
      const mask = String(options.mask ?? 'xyz');
      const idx = [...mask].map((c) => SWIZZLE[c]);
      if (idx.some((i) => i === undefined)) throw new DerivedProgramError(`${what}: bad swizzle mask '${mask}'`);
      return ([a]) => [idx.map((i) => a[i])];
    }
    case 'split':
      return ([a]) => outputs.map((m, i) => (m ? [a[i]] : []));
    case 'combine':
      return (xs) => [xs.slice(0, n).map((x) => x[0])];
    case 'remap': {
      const clamped = options.clamp === true;
      return ([x, a, b, lo, hi]) => {
        const r = new Array(n);
        for (let i = 0; i < n; ++i) {
          const ai = at(a, i), bi = at(b, i);
          let t = bi === ai ? 0 : (at(x, i) - ai) / (bi - ai);
          if (clamped) t = clamp(t, 0, 1);
          r[i] = mix(at(lo, i), at(hi, i), t);
        }
        return [r];
      };
    }
    case 'srgb_to_linear':  // per colour component; a vec4's alpha as it is
      return ([c]) => [Array.from({ length: n }, (_, i) => (i === 3 ? at(c, i) : srgbToLinear(at(c, i))))];
    default:
      throw new DerivedProgramError(`${what}: node type '${type}' cannot be computed outside the shader`);
  }
}

// program: a manifest uniform's "derived" entry. Returns (parameters, draw) => number[]:
// `parameters` maps a parameter's name to its value (a number or an array, already clamped
// into its range), `draw` holds the DERIVED_BUILTINS (arrays; time a number).
export function compileDerived(program, what = 'derived uniform') {
  if (!isObject(program) || !Array.isArray(program.ops) || !isObject(program.value))
    throw new DerivedProgramError(`${what}: needs "ops" and "value"`);
  const steps = program.ops.map((op, k) => {
    if (!isObject(op)) throw new DerivedProgramError(`${what}, op ${k}: not an object`);
    const name = `${what}, op ${k} ('${op.node ?? ''}')`;
    const fn = opFunction(op, name);
    const inputs = (Array.isArray(op.inputs) ? op.inputs : []).map((input, i) => {
      if (!isObject(input)) throw new DerivedProgramError(`${name}: input ${i} is not an object`);
      if ('op' in input) {
        const j = input.op, port = input.port ?? 0;
        if (!(Number.isInteger(j) && j >= 0 && j < k)) throw new DerivedProgramError(`${name}: input ${i} reads no earlier op`);
        if (!isPort(program.ops[j], port)) throw new DerivedProgramError(`${name}: input ${i} reads no output of op ${j}`);
        return (values) => values[j][port];
      }
      if ('parameter' in input) {
        const p = String(input.parameter);
        return (values, parameters) => {
          const v = own(parameters, p) ? parameters[p] : undefined;
          if (v === undefined) throw new DerivedProgramError(`${name}: parameter '${p}' has no value`);
          return typeof v === 'number' ? [v] : Array.from(v);
        };
      }
      if ('builtin' in input) {
        const b = String(input.builtin);
        if (!DERIVED_BUILTINS.includes(b)) throw new DerivedProgramError(`${name}: '${b}' is no per-draw builtin`);
        return (values, parameters, draw) => (typeof draw[b] === 'number' ? [draw[b]] : Array.from(draw[b]));
      }
      if ('constant' in input) {
        if (!Array.isArray(input.constant)) throw new DerivedProgramError(`${name}: input ${i} is a constant that is not an array`);
        const c = input.constant.map(Number);
        return () => c;
      }
      throw new DerivedProgramError(`${name}: input ${i} is none of op, parameter, builtin, constant`);
    });
    // An op with fewer inputs than its type would read past them at the first draw.
    if (inputs.length !== arityOf(op.type))
      throw new DerivedProgramError(`${name}: ${inputs.length} inputs; a '${op.type}' has ${arityOf(op.type)}`);
    // A float read by a wider port splats over its components, as the CPU backend converts it.
    const widths = listOf(op.input_types).map((t) => componentsOf(t, name));
    if (widths.length !== inputs.length) throw new DerivedProgramError(`${name}: inputs and input types apart`);
    const widened = inputs.map((read, i) => (values, parameters, draw) => {
      const v = read(values, parameters, draw);
      return v.length === 1 && widths[i] > 1 ? new Array(widths[i]).fill(v[0]) : v;
    });
    return { fn, inputs: widened };
  });
  const { op: root, port = 0 } = program.value;
  if (!(Number.isInteger(root) && root >= 0 && root < steps.length) || !isPort(program.ops[root], port))
    throw new DerivedProgramError(`${what}: the value is no op output`);
  return (parameters, draw) => {
    const values = [];
    for (const s of steps) values.push(s.fn(s.inputs.map((input) => input(values, parameters, draw)), draw));
    return values[root][port];
  };
}

// The draw values as the runtime gives them to derived programs: near and far each clamped
// into [1e-6, 1e30], NaN to 1e-6.
export function drawValues({ time = 0, cameraPosition = [0, 0, 0], near = 0.1, far = 100, view, projection, sunDirection = [0, 1, 0] }) {
  const plane = (x) => (!(x >= 1e-6) ? 1e-6 : Math.min(x, 1e30));
  const identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  return {
    time,
    camera_position: Array.from(cameraPosition),
    camera_near_far: [plane(near), plane(far)],
    view: Array.from(view ?? identity),
    projection: Array.from(projection ?? identity),
    sun_direction: Array.from(sunDirection),
  };
}
