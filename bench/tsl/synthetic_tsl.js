// The synthetic graph of bench/synthetic_graph.cpp as three.js TSL: the same blocks, the same
// choices (the same LCG), each watergraph node one TSL call (a node of ours with no TSL
// counterpart, Gerstner waves, Schlick's Fresnel and the depth tint, is one call of a TSL
// Fn written here). Used by tsl_bench.html to time GLSLNodeBuilder.build() against
// watergraph's front end on graphs of the same size and shape.
//
// buildSynthetic(nodes, TSL) returns { colorNode, opacityNode, positionNode, normalNode,
// count }: the material's nodes and the number of our nodes the port made (the C++
// generator's count for the same `nodes`).

export function buildSynthetic(nodes, TSL) {
  const {
    Fn, float, vec3, uniform, uv, positionWorld, normalWorld, positionLocal, normalView, positionViewDirection,
    time, mul, add, sub, sin, cos, dot, mix, smoothstep, clamp, normalize, exp, pow, max,
    mx_worley_noise_float, mx_noise_float, mx_fractal_noise_float,
  } = TSL;
  nodes = Math.max(nodes, 10);
  const params = Math.min(Math.max(Math.floor(nodes / 200), 1), 16);
  const gain = [], depth = [];
  for (let j = 0; j < params; ++j) {
    gain.push(uniform(1 + 0.01 * j));
    depth.push(uniform(4 + j));
  }
  const tint = uniform(vec3(0, 0.4, 0.6));
  const slope = float(0.25);  // a static parameter: a constant

  // Our nodes with no TSL counterpart, each one Fn (called once per node of ours).
  const gerstner = Fn(([p]) => {
    const waves = [[[1, 0.3], 0.4, 8], [[-0.2, 1], 0.2, 3]];
    let out = p;
    for (const [[dx, dz], q, length] of waves) {
      const norm = Math.hypot(dx, dz), k = (2 * Math.PI) / length, c = Math.sqrt(9.81 / k);
      const phase = mul(k, add(mul(dx / norm, p.x), mul(dz / norm, p.z))).sub(mul(k * c, time));
      const a = q / k;
      out = add(out, vec3(mul(a * dx / norm, cos(phase)), mul(a, sin(phase)), mul(a * dz / norm, cos(phase))));
    }
    return out;
  });
  const gerstnerNormal = Fn(([p]) => {
    const k = (2 * Math.PI) / 8, phase = mul(k, p.x).sub(mul(k * Math.sqrt(9.81 / k), time));
    return normalize(vec3(mul(-0.4, cos(phase)), 1, mul(-0.12, cos(phase))));
  });
  const schlick = Fn(([f0]) => {
    const c = clamp(dot(normalView, positionViewDirection), 0, 1);
    return add(f0, mul(sub(1, f0), pow(sub(1, c), 5)));
  });
  const depthTint = Fn(([d, maxDepth]) => exp(mul(-3, clamp(d.div(max(maxDepth, 1e-4)), 0, 1))));

  let count = 0;
  const full = () => count >= nodes;
  const node = (make) => {
    if (full()) return null;
    ++count;
    return make();
  };
  const uvNode = node(() => uv());
  const pos = node(() => positionWorld);
  const nrm = node(() => normalWorld);
  const waves = node(() => ({ position: gerstner(positionLocal), normal: gerstnerNormal(positionLocal) }));
  node(() => null);  // vertex_output: the material's position and normal nodes below
  const clock = node(() => time);

  const floats = [clock], vec3s = [pos, nrm, tint];
  let f = floats[0], c = vec3s[0], alpha = f, color = c;
  let lcg = 12345;
  const pick = (from) => {
    lcg = (Math.imul(lcg, 1664525) + 1013904223) >>> 0;
    return from[(lcg >>> 8) % from.length];
  };
  const num = (x) => float(Number(x.toPrecision(4)));

  for (let i = 0; !full(); ++i) {
    const k = 0.5 + (i % 997) * 0.003;
    const g = gain[i % params], dep = depth[i % params];
    const skipF = pick(floats), skipC = pick(vec3s);
    const scale = node(() => mul(f, i % 7 === 0 ? g : num(k)));
    if (!scale) break;
    alpha = scale;
    const wave = node(() => sin(scale));
    if (!wave) break;
    alpha = wave;
    let water;
    switch (i % 6) {
      case 0: water = node(() => schlick(num(0.02 + 0.0001 * (i % 50)))); break;
      case 1: water = node(() => mx_worley_noise_float(mul(uvNode, num(4 + k)))); break;
      case 2: water = node(() => mx_noise_float(mul(uvNode, num(8 * k)))); break;
      case 3: water = node(() => depthTint(wave, dep)); break;
      case 4: water = node(() => smoothstep(0, num(k), skipF)); break;
      default: water = node(() => mx_fractal_noise_float(mul(uvNode, num(3 * k)), 3)); break;
    }
    if (!water) break;
    const sum = node(() => add(wave, water));
    if (!sum) break;
    alpha = sum;
    const mixed = node(() => mix(c, skipC, sum));
    if (!mixed) break;
    color = mixed;
    const lit = node(() => dot(mixed, nrm));
    if (!lit) break;
    alpha = lit;
    const sixth = node(() => (i % 2 === 0 ? sin(scale) : clamp(lit, 0, 1)));
    if (!sixth) break;
    const out = node(() => mul(lit, sixth));
    if (!out) break;
    alpha = out;
    let base = mixed, offset = out;
    if (i % 10 === 9) {
      if (!node(() => sub(out, 1))) break;  // a debug node nobody reads
    } else if (i % 10 === 4) {
      const konst = node(() => mul(num(k), i % 20 === 4 ? slope : float(2)));
      if (!konst) break;
      offset = konst;
    } else {
      const norm = node(() => normalize(mixed));
      if (!norm) break;
      base = norm;
    }
    const col = node(() => add(base, offset));
    if (!col) break;
    color = col;
    f = out;
    c = color;
    floats.push(sum, f);
    vec3s.push(mixed, c);
  }
  return { colorNode: color, opacityNode: alpha, positionNode: waves.position, normalNode: waves.normal, count };
}
