#!/usr/bin/env python3
# Renders every pipeline (and the options that change attachment formats, MSAA and the texture
# cache shape) on the demo scene and a small generated atrium at 1 and 2 threads, keeping the
# images and the JSON reports without their timings; `compare` says whether two such runs (e.g.
# a build of main and a changed build) agree bit for bit. Used to prove performance work
# changes no output.
#   scripts/bit_identity_check.py render BUILD/ontile OUT_DIR [--size 480x270]
#   scripts/bit_identity_check.py compare DIR_A DIR_B
import argparse
import filecmp
import json
import os
import subprocess
import sys

VARIANTS = [
    ("lambert", []),
    ("lambert", ["--set", "msaa=4"]),
    ("lambert", ["--set", "depth=d16", "--set", "normals=oct-rg16"]),
    ("lambert", ["--set", "depth=d24", "--set", "normals=rgba16f"]),
    ("forward", []),
    ("forward", ["--set", "msaa=4"]),
    ("forward", ["--set", "msaa=2", "--set", "resolve=separate"]),
    ("deferred-subpass", []),
    ("deferred-subpass", ["--gbuffer", "unity"]),
    ("deferred-classic", []),
    ("deferred-classic", ["--gbuffer", "vulkan-samples-large"]),
    ("cartoon", []),
    ("cartoon", ["--texture-cache-kib", "16"]),
    ("cartoon", ["--texture-cache-kib", "2048"]),
    ("cartoon-multipass", []),
    ("cartoon-hull", []),
    ("universal", []),
]


def without_timing(value):
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items()
                if k not in ("timing", "threads") and not k.endswith("_ms")}
    if isinstance(value, list):
        return [without_timing(v) for v in value]
    return value


def render(args):
    os.makedirs(args.out_dir, exist_ok=True)
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    atrium = os.path.join(args.out_dir, "atrium.glb")
    subprocess.run([args.ontile, "gen-scene", "atrium", "--size", "0.25", "--out", atrium],
                   check=True, stdout=subprocess.DEVNULL)
    scenes = {"demo": os.path.join(repo, "scenes", "demo.glb"), "atrium": atrium}
    for scene_name, scene in scenes.items():
        for index, (pipeline, options) in enumerate(VARIANTS):
            for threads in (1, 2):
                stem = os.path.join(args.out_dir, f"{scene_name}_{index:02d}_{pipeline}_t{threads}")
                subprocess.run([args.ontile, "render", "--scene", scene, "--pipeline", pipeline,
                                "--size", args.size, "--threads", str(threads), "--out",
                                stem + ".png", "--report", stem + ".raw.json"] + options,
                               check=True, stdout=subprocess.DEVNULL)
                with open(stem + ".raw.json") as f:
                    report = without_timing(json.load(f))
                # The scene's path says where the run was made (a worktree, an output folder
                # holding the generated atrium), not what was rendered: two checkouts must agree.
                report["run"]["scene"] = os.path.basename(report["run"]["scene"])
                os.remove(stem + ".raw.json")
                with open(stem + ".json", "w") as f:
                    json.dump(report, f, indent=1, sort_keys=True)
    return 0


def compare(args):
    names = sorted(n for n in os.listdir(args.dir_a) if n.endswith((".png", ".json")))
    other = sorted(n for n in os.listdir(args.dir_b) if n.endswith((".png", ".json")))
    if names != other:
        print("the runs hold different files")
        return 1
    differing = [n for n in names
                 if not filecmp.cmp(os.path.join(args.dir_a, n), os.path.join(args.dir_b, n),
                                    shallow=False)]
    for n in differing:
        print("differs:", n)
    print(f"{len(names) - len(differing)} of {len(names)} files identical")
    return 1 if differing else 0


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest="command", required=True)
    r = sub.add_parser("render")
    r.add_argument("ontile")
    r.add_argument("out_dir")
    r.add_argument("--size", default="480x270")
    c = sub.add_parser("compare")
    c.add_argument("dir_a")
    c.add_argument("dir_b")
    args = parser.parse_args()
    return render(args) if args.command == "render" else compare(args)


if __name__ == "__main__":
    sys.exit(main())
