#!/usr/bin/env python3
"""The cost model of docs/benchmarks.md: per pass, GPU time against the work it counted.

Reads a bench.json (`monoplane bench ... --out DIR`) and fits, by least squares over every run
of the file, the unit costs of each kind of pass on that device:

  forward passes (left/right/eyes/mono.forward):  ms = a * primitives + b * fragments
  full-screen passes (composite, tonemap, taa):   ms = c * pixels covered
  (a composite that tone maps into the display image itself, the plan's "writes_display", is
  fitted as its own kind, composite+tonemap, over the eye's pixels; its eye's tonemap pass then
  draws only in frames whose C had nothing, and is left out of the fit)

Primitives are the view's clipping invocations and fragments its fragment-shader invocations
(llvmpipe counts every covered pixel of every 2x2 quad, before the depth test rejects any). Then,
per configuration, it prints the measured frame time beside the modelled one (the sum of its
passes' work at those unit costs: the time if every pass cost only its work) and names the pass
that takes most of it. A frame much slower than its model pays for something the counters do not
see (barriers, clears, idle waits).

Usage: scripts/cost_model.py out/bench/bench.json [--markdown]
"""

import argparse
import json
import sys



def forward_rows(runs):
    """(ms, primitives, fragments) of every forward pass of every run."""
    rows = []
    for run in runs:
        for name, ms in run["passes"].items():
            if not name.endswith(".forward"):
                continue
            view = name[: -len(".forward")]
            if view not in run["view_primitives"]:
                continue
            rows.append((ms, run["view_primitives"][view], run["view_fragments"].get(view, 0)))
    return rows


def screen_kind(run, name):
    """The kind a full-screen pass is fitted as, or None for a tone mapping whose work the
    composite did (its draw runs only when C had nothing to draw)."""
    view, _, kind = name.partition(".")
    fused = {p["pass"] for p in run.get("plan", []) if p.get("writes_display")}
    if kind == "composite" and name in fused:
        return "composite+tonemap"
    if kind == "tonemap" and f"{view}.composite" in fused:
        return None
    return kind


def fullscreen_pixels(run, name, eye_pixels):
    """Pixels a full-screen pass covers (its own counter where it has one)."""
    view = name.split(".")[0]
    if screen_kind(run, name) == "composite+tonemap":
        return eye_pixels  # both draws' counters together cover every pixel twice
    if name.endswith(".composite"):
        return run["view_fragments"].get(name, eye_pixels)
    if view == "mono":
        return None  # C's tone mapping runs only for read-backs, which bench does not take
    return eye_pixels


def least_squares_2(rows):
    """(a, b) minimising the sum of (ms - a x - b y)^2 over rows (ms, x, y): the normal equations,
    solved by Cramer's rule (two unknowns need no numerics library)."""
    sxx = sum(x * x for _, x, _ in rows)
    sxy = sum(x * y for _, x, y in rows)
    syy = sum(y * y for _, _, y in rows)
    sx = sum(ms * x for ms, x, _ in rows)
    sy = sum(ms * y for ms, _, y in rows)
    det = sxx * syy - sxy * sxy
    if det == 0:
        sys.exit("cost_model: primitives and fragments are proportional; cannot separate them")
    return (sx * syy - sy * sxy) / det, (sxx * sy - sxy * sx) / det


def fit(report):
    runs = report["runs"]
    eye_pixels = report["width"] * report["height"]
    rows = forward_rows(runs)
    if len(rows) < 2:
        sys.exit("cost_model: need at least two forward passes in the bench")
    per_primitive, per_fragment = least_squares_2(rows)
    screen = {}
    for kind in ("composite", "composite+tonemap", "tonemap", "taa"):
        t, px = [], []
        for run in runs:
            for name, value in run["passes"].items():
                if screen_kind(run, name) == kind:
                    pixels = fullscreen_pixels(run, name, eye_pixels)
                    if pixels:
                        t.append(value)
                        px.append(pixels)
        if t:
            screen[kind] = sum(a * b for a, b in zip(t, px)) / sum(b * b for b in px)
    return per_primitive, per_fragment, screen


def modelled_passes(run, model, eye_pixels):
    per_primitive, per_fragment, screen = model
    out = {}
    for name, ms in run["passes"].items():
        view, _, kind = name.partition(".")
        if kind == "forward" and view in run["view_primitives"]:
            out[name] = (per_primitive * run["view_primitives"][view]
                         + per_fragment * run["view_fragments"].get(view, 0))
        elif screen_kind(run, name) in screen:
            kind = screen_kind(run, name)
            pixels = fullscreen_pixels(run, name, eye_pixels)
            if pixels:
                out[name] = screen[kind] * pixels
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bench_json")
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    args = parser.parse_args()
    with open(args.bench_json) as f:
        report = json.load(f)
    model = fit(report)
    per_primitive, per_fragment, screen = model
    eye_pixels = report["width"] * report["height"]
    print(f"device: {report['device']}, {report['width']} x {report['height']} per eye")
    print(f"forward: {per_primitive * 1e6:.1f} ns per primitive, "
          f"{per_fragment * 1e6:.2f} ns per fragment invocation")
    for kind, ms_per_pixel in screen.items():
        print(f"{kind}: {ms_per_pixel * 1e6:.2f} ns per pixel")
    header = ["scene", "mode", "variant", "m", "lod", "measured ms", "modelled ms", "modelled/measured",
              "largest pass (modelled ms)"]
    if args.markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
    for run in report["runs"]:
        passes = modelled_passes(run, model, eye_pixels)
        modelled = sum(passes.values())
        largest = max(passes.items(), key=lambda item: item[1]) if passes else ("-", 0.0)
        m = "far" if run.get("mono_plane_is_far") else (
            "-" if run["mono_plane"] is None else f"{run['mono_plane']:g}")
        cells = [run["scene"], run["mode"], run["variant"] or "-", m, run.get("lod", "off"),
                 f"{run['frame_ms_median']:.1f}", f"{modelled:.1f}",
                 f"{modelled / run['frame_ms_median']:.2f}",
                 f"{largest[0]} ({largest[1]:.1f})"]
        print(("| " + " | ".join(cells) + " |") if args.markdown else "  ".join(cells))


if __name__ == "__main__":
    main()
