#!/usr/bin/env python3
"""scripts/cost_model.py on a bench.json whose pass times are made from known unit costs: the fit
must recover them, and every configuration's modelled time must equal its measured one when the
frame is exactly the sum of its passes' work. Exits non-zero on the first mismatch."""

import json
import pathlib
import re
import subprocess
import sys
import tempfile

PER_PRIMITIVE_MS = 50e-6   # 50 ns
PER_FRAGMENT_MS = 12e-6    # 12 ns
COMPOSITE_MS = 9e-6        # per pixel
TONEMAP_MS = 4e-6          # per pixel
WIDTH, HEIGHT = 100, 80


def forward_ms(primitives, fragments):
    return PER_PRIMITIVE_MS * primitives + PER_FRAGMENT_MS * fragments


def run(views, composites):
    """One configuration: views maps a view to (primitives, fragments)."""
    pixels = WIDTH * HEIGHT
    passes = {f"{v}.forward": forward_ms(p, f) for v, (p, f) in views.items()}
    fragments = {v: f for v, (_, f) in views.items()}
    for eye in ("left", "right"):
        passes[f"{eye}.tonemap"] = TONEMAP_MS * pixels
        if composites:
            passes[f"{eye}.composite"] = COMPOSITE_MS * pixels
            fragments[f"{eye}.composite"] = pixels
    return {
        "scene": "synthetic", "mode": "hybrid" if "mono" in views else "stereo", "variant": "",
        "mono_plane": 8.0 if "mono" in views else None, "mono_plane_is_far": False,
        "frame_ms_median": sum(passes.values()), "passes": passes,
        "view_primitives": {v: p for v, (p, _) in views.items()}, "view_fragments": fragments,
    }


def main():
    runs = [
        run({"left": (200000, 2500000), "right": (201000, 2400000)}, composites=False),
        run({"left": (30000, 900000), "right": (31000, 950000), "mono": (150000, 1600000)}, True),
        run({"left": (60000, 400000), "right": (59000, 420000), "mono": (90000, 2100000)}, True),
    ]
    report = {"device": "synthetic", "width": WIDTH, "height": HEIGHT, "runs": runs}
    script = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "cost_model.py"
    with tempfile.TemporaryDirectory() as folder:
        path = pathlib.Path(folder) / "bench.json"
        path.write_text(json.dumps(report))
        out = subprocess.run([sys.executable, str(script), str(path), "--markdown"],
                             check=True, capture_output=True, text=True).stdout
    fit = re.search(r"forward: ([\d.]+) ns per primitive, ([\d.]+) ns per fragment", out)
    assert fit, out
    assert abs(float(fit.group(1)) - 50.0) < 0.05, out
    assert abs(float(fit.group(2)) - 12.0) < 0.005, out
    assert re.search(r"composite: 9\.00 ns per pixel", out), out
    assert re.search(r"tonemap: 4\.00 ns per pixel", out), out
    rows = [line for line in out.splitlines() if line.startswith("| synthetic")]
    assert len(rows) == len(runs), out
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        assert cells[4] == "off", row  # runs without a "lod" key: full detail
        assert cells[7] == "1.00", row  # modelled / measured
    # The largest modelled pass of the second run is C's forward pass.
    assert "mono.forward" in rows[1], rows[1]
    print("cost_model_test: 3 configurations, unit costs recovered")


if __name__ == "__main__":
    main()
