#!/usr/bin/env python3
"""The blended-surfaces table of docs/benchmarks.md: per-eye transparency after the composite.

Reads two bench.json files of the same command, one over the blended pane field and one over
the same panes opaque (`tests/tools/gltf_pane_field [--opaque]`, then `monoplane bench --scenes
FILE --modes stereo,hybrid ... --out DIR`), and prints one Markdown row per configuration of the
blended run: hybrid's time against stereo (bench's paired median, `time_ratio_vs_stereo`, with
its quartiles) for the blended and the opaque field, the blended frame's GPU passes (both eyes
summed; the tone mapping also the opaque field's: there the composite tone maps itself and the
tonemap passes are left empty), the share of the frame the eyes' transparency passes take, and
their fragment invocations. Frame times are each configuration's own median, in brackets that of the stereo
frames rendered between its frames (both drift with the machine's load; the ratios pair them).

Optionally, `monoplane render --json` statistics (stats.json, one per mono plane, of the blended
field in hybrid mode at a finite m) give how many panes each view drew: C's are the chunks in
C's list before occlusion culling (draws_before_occlusion_culling) less the field's one opaque
chunk (ground and backdrop, which reaches beyond every m), an eye's are its transparency pass's
input primitives over two (two triangles a pane). In stereo and at m = far the eyes' forward
passes draw every pane ("all"). (bench.json itself now reports each transparency pass's draws
and primitives; the runs of the table predate that.)

Usage: scripts/blended_panes_table.py BLEND/bench.json OPAQUE/bench.json
           [--render M3/stats.json M8/stats.json ...]
"""

import argparse
import json


def load_runs(path):
    with open(path) as f:
        return json.load(f)["runs"]


def key(run):
    if run["mode"] == "stereo":
        return ("stereo", None)
    return (run["mode"], "far" if run["mono_plane_is_far"] else run["mono_plane"])


def ratio(run):
    """Bench's paired time ratio to stereo with its quartiles (stereo itself: 1)."""
    if run["mode"] == "stereo" or run.get("time_ratio_p25") is None:
        return "1.00x"
    return (f"{run['time_ratio_vs_stereo']:.2f}x [{run['time_ratio_p25']:.2f}, "
            f"{run['time_ratio_p75']:.2f}]")


def both(passes, kind):
    return passes.get("left." + kind, 0.0) + passes.get("right." + kind, 0.0)


def pane_counts(render_paths):
    """{m: (C's panes, left eye's, right eye's)} from render stats.json files."""
    counts = {None: (0, "all", "all"), "far": (0, "all", "all")}
    for path in render_paths:
        with open(path) as f:
            stats = json.load(f)
        views = stats["views"]
        mono = views["mono"]["draws_before_occlusion_culling"] - 1
        eyes = [views[e + ".transparency"]["input_primitives"] // 2 for e in ("left", "right")]
        counts[stats["mono_plane"]] = (mono, eyes[0], eyes[1])
    return counts


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("blend")
    parser.add_argument("opaque")
    parser.add_argument("--render", nargs="*", default=[])
    args = parser.parse_args()
    blend = load_runs(args.blend)
    opaque = {key(run): run for run in load_runs(args.opaque)}
    counts = pane_counts(args.render) if args.render else {}

    print("| mode | m | panes C / left / right | time vs stereo, blended | time vs stereo, opaque "
          "| frame ms, blended (paired stereo) | eyes' forward ms | C ms | composite ms | transparency ms "
          "| tonemap ms, blended / opaque "
          "| transparency share | transparency fragments |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for run in blend:
        k = key(run)
        passes = run["passes"]
        frame = run["frame_ms_median"]
        transparency = both(passes, "transparency")
        other = opaque.get(k)
        m = "-" if k[1] is None else (k[1] if k[1] == "far" else f"{k[1]:g}")
        c = counts.get(k[1])
        panes = "-" if c is None else f"{c[0]} / {c[1]} / {c[2]}"
        stereo_ms = run.get("stereo_frame_ms_median")
        paired = "" if run["mode"] == "stereo" or stereo_ms is None else f" ({stereo_ms:.0f})"
        fragments = (run["view_fragments"].get("left.transparency", 0)
                     + run["view_fragments"].get("right.transparency", 0))
        print(f"| {run['mode']} | {m} | {panes} | {ratio(run)} "
              f"| {'-' if other is None else ratio(other)} | {frame:.0f}{paired} "
              f"| {both(passes, 'forward'):.0f} | {passes.get('mono.forward', 0.0):.0f} "
              f"| {both(passes, 'composite'):.1f} | {transparency:.0f} "
              f"| {both(passes, 'tonemap'):.1f} / "
              f"{'-' if other is None else format(both(other['passes'], 'tonemap'), '.1f')} "
              f"| {100.0 * transparency / frame:.0f} % | {fragments / 1e6:.2f}M |")


if __name__ == "__main__":
    main()
