// Evaluates derived programs with the client's evaluator (watergraph-derived.js) for
// watergraph's tests: reads {"programs": [program, ...], "cases": [{"parameters": {name:
// value}, "draw": {...}}]} from the file named on the command line and prints
// {"results": [[value per program] per case]}. JSON has no NaN or infinity: in the input null
// stands for NaN, in the output "nan", "inf" and "-inf" for those.
import { readFileSync } from 'node:fs';
import { compileDerived, drawValues } from '../watergraph-derived.js';

const input = JSON.parse(readFileSync(process.argv[2], 'utf8'));
const nan = (x) => (x === null ? NaN : x);
const functions = input.programs.map((p, i) => compileDerived(p, `program ${i}`));
const results = input.cases.map((c) => {
  const parameters = {};
  for (const [name, v] of Object.entries(c.parameters)) parameters[name] = Array.isArray(v) ? v.map(nan) : nan(v);
  const d = c.draw;
  const draw = drawValues({ time: nan(d.time), cameraPosition: d.camera_position.map(nan), near: nan(d.near), far: nan(d.far), sunDirection: d.sun_direction.map(nan), view: d.view.map(nan) });
  return functions.map((f) => f(parameters, draw));
});
const encode = (x) => (Number.isNaN(x) ? 'nan' : x === Infinity ? 'inf' : x === -Infinity ? '-inf' : x);
process.stdout.write(JSON.stringify({ results: results.map((r) => r.map((v) => v.map(encode))) }));
