#!/usr/bin/env python3
"""Where an open_ocean frame's CPU time goes on llvmpipe, by taking parts of the graph away.

Each variant of graphs/open_ocean.json is rendered by `watergraph render` twice, with one
frame and with 1 + FRAMES frames at one time; the difference of the two processes' CPU time
(user + system, llvmpipe's threads included, from getrusage of the children), divided by
FRAMES, is a frame's cost without the first frame's shader compiles and simulation (frames
at one held time run no simulation: runtime/ocean_simulation.h). CPU time, not wall time:
on a shared machine wall time grows with the other programs' load.

Variants (the water's graph; the built-in scene and its sky stay, unless --scene none):
  as written        the graph
  no foam           ocean_foam taken out (the whitecaps of the Jacobian stay)
  no detail         ocean_surface and ocean_foam taken out: the fragment stage lights the
                    vertex normal
  no sky reflection fresnel_sky's cube-map reflection replaced by a constant colour (no
                    environment_cubemap pass)
  constant colour   the fragment stage one colour (the vertex stage still displaces)
  flat sheet        no ocean at all: an undisplaced sheet of one colour (no simulation)

  python3 bench/ocean_frame_share.py build [--size 160x90] [--frames 40] [--cameras above,grazing,topdown]
"""
import argparse
import copy
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile


def rewire(graph, old, new):
    for node in graph["nodes"]:
        for port, source in node.get("inputs", {}).items():
            if source == old:
                node["inputs"][port] = new


def drop(graph, ids):
    graph["nodes"] = [n for n in graph["nodes"] if n["id"] not in ids]


def variants(graph):
    out = {"as written": graph}
    g = copy.deepcopy(graph)
    rewire(g, "foam.foam", 0)
    drop(g, {"foam"})
    out["no foam"] = g
    g = copy.deepcopy(out["no foam"])
    rewire(g, "detail.normal", "displaced.normal")
    rewire(g, "detail.jacobian", 1.0)
    drop(g, {"detail"})
    out["no detail"] = g
    g = copy.deepcopy(graph)
    for n in g["nodes"]:
        if n["id"] == "body":
            n["type"], n["inputs"] = "mix", {"a": "$deep_color", "b": [0.5, 0.6, 0.8], "t": 0.05}
    rewire(g, "body.color", "body.out")
    out["no sky reflection"] = g
    g = copy.deepcopy(graph)
    g["outputs"]["fragment"] = {"color": "$deep_color"}
    out["constant colour"] = g
    g = copy.deepcopy(graph)
    g["nodes"] = [{"id": "surface", "type": "vertex_output"}]
    g["outputs"] = {"vertex": {"position": "surface.position", "normal": "surface.normal"},
                    "fragment": {"color": "$deep_color"}}
    g["presets"] = {}
    out["flat sheet"] = g
    return out


def children_cpu_s():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def render_cpu_s(watergraph, path, camera, size, frames, scene):
    before = children_cpu_s()
    cmd = ["nice", watergraph, "render", path, "-o", path + ".png", "--size", size,
           "--camera", camera, "--time", "1", "--frames", str(frames), "--scene", scene]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"ocean_frame_share: {' '.join(cmd)} failed:\n{r.stderr}")
    return children_cpu_s() - before


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("--graph", default=os.path.join(os.path.dirname(__file__), "..", "graphs", "open_ocean.json"))
    ap.add_argument("--size", default="160x90")
    ap.add_argument("--frames", type=int, default=40)
    ap.add_argument("--cameras", default="above,grazing,topdown")
    ap.add_argument("--scene", default="builtin", choices=["builtin", "none"])
    a = ap.parse_args()
    watergraph = os.path.join(a.build, "bin", "watergraph")
    graph_path = os.path.abspath(a.graph)
    graph = json.load(open(graph_path))
    work = tempfile.mkdtemp(prefix="wg_ocean_share_")
    try:
        # The variants beside a copy of the graph's folder, so that its imports resolve.
        shutil.copytree(os.path.dirname(graph_path), os.path.join(work, "graphs"))
        cameras = a.cameras.split(",")
        print(f"{os.path.basename(graph_path)}, {a.size}, scene {a.scene}, CPU ms per frame "
              f"((CPU of 1 + {a.frames} frames - CPU of 1 frame) / {a.frames})\n")
        print("| variant | " + " | ".join(cameras) + " | sum | share of as written |")
        print("|---|" + "---|" * (len(cameras) + 2))
        reference = None
        for name, g in variants(graph).items():
            path = os.path.join(work, "graphs", name.replace(" ", "_") + ".json")
            json.dump(g, open(path, "w"), indent=1)
            per_camera = []
            for cam in cameras:
                one = render_cpu_s(watergraph, path, cam, a.size, 1, a.scene)
                many = render_cpu_s(watergraph, path, cam, a.size, 1 + a.frames, a.scene)
                per_camera.append(1000.0 * (many - one) / a.frames)
            total = sum(per_camera)
            reference = reference or total
            print(f"| {name} | " + " | ".join(f"{x:.1f}" for x in per_camera) + f" | {total:.1f} | {total / reference:.2f} |",
                  flush=True)
    finally:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
