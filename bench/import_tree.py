#!/usr/bin/env python3
"""Writes a tree of graph files whose inlined size doubles at every level.

The hostile shape of issue 40 (class 1): `top.json` and `--levels` files under `lib/`,
each level instancing the next one `--fan` times in a chain (each instance reads the one
before, so nothing folds or merges), the last one a few math nodes on its input. Ids are
`--id-length` characters long, so every inlined op's id (`a.../b.../...`) grows with the
depth. With the defaults (16 levels, fan 2, 3 leaf nodes, 64-character ids) the graph has
2^16 * 3 + 1 = 196,609 nodes inlined, from about 10 KB of files.

    bench/import_tree.py OUT_DIR [--levels 16] [--fan 2] [--leaf 3] [--id-length 64]
    build/bin/watergraph validate OUT_DIR/top.json

tests/robustness/import_budget_test.cpp writes the same shape from C++.
"""
import argparse
import json
import os


def long_id(stem, length):
    return (stem + "_" + "x" * length)[:length]


def write(path, graph):
    with open(path, "w", encoding="utf-8") as f:
        json.dump(graph, f, indent=1)
        f.write("\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--levels", type=int, default=16)
    ap.add_argument("--fan", type=int, default=2)
    ap.add_argument("--leaf", type=int, default=3)
    ap.add_argument("--id-length", type=int, default=64)
    ap.add_argument("--leaf-type", default="sin", help="the node type of the leaf nodes (one input, x)")
    ap.add_argument("--parallel", action="store_true",
                    help="every instance of a level reads the level's input and an add node sums them "
                         "(common subexpressions: the passes merge the copies) instead of a chain")
    a = ap.parse_args()
    os.makedirs(os.path.join(a.out, "lib"), exist_ok=True)

    def chain(next_name, fan, first_input):
        nodes, prev = [], first_input
        for k in range(fan):
            nid = long_id("i%d" % k, a.id_length)
            nodes.append({"id": nid, "type": next_name, "inputs": {"x": first_input if a.parallel else prev}})
            if a.parallel and k > 0:
                sid = long_id("s%d" % k, a.id_length)
                nodes.append({"id": sid, "type": "add", "inputs": {"a": prev, "b": nid + ".v"}})
                prev = sid + ".out"
            else:
                prev = nid + ".v"
        return nodes, prev

    for level in range(1, a.levels + 1):
        g = {"version": 1, "name": "level%d" % level,
             "parameters": {"x": {"type": "float", "default": 0.5}}}
        if level < a.levels:
            g["imports"] = {"next": "l%02d.json" % (level + 1)}
            nodes, last = chain("next", a.fan, "$x")
        else:
            nodes, prev = [], "$x"
            for k in range(a.leaf):
                nid = long_id("m%d" % k, a.id_length)
                nodes.append({"id": nid, "type": a.leaf_type, "inputs": {"x": prev}})
                prev = nid + ".out"
            last = prev
        g["interface"] = {"outputs": {"v": {"type": "float", "source": last}}}
        g["nodes"] = nodes
        write(os.path.join(a.out, "lib", "l%02d.json" % level), g)

    t = long_id("t", a.id_length)
    nodes, last = chain("tree", a.fan, t + ".out")
    write(os.path.join(a.out, "top.json"),
          {"version": 1, "name": "top", "imports": {"tree": "lib/l01.json"},
           "nodes": [{"id": t, "type": "time"}] + nodes,
           "outputs": {"fragment": {"alpha": last}}})


if __name__ == "__main__":
    main()
