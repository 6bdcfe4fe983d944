#!/usr/bin/env python3
"""Runs Khronos' hello_xr (a real OpenXR application simxr's authors did not write) against simxr
through a whole session, and checks what it rendered (docs/simxr.md, "Running any OpenXR
application on simxr").

  hello_xr_test.py MANIFEST WORK_DIR scene   default profile; the scene's cubes are drawn
  hello_xr_test.py MANIFEST WORK_DIR grab    microsoft/motion_controller; a scripted squeeze
                                             shrinks hello_xr's right-hand cube
  hello_xr_test.py MANIFEST WORK_DIR runtime_list   openxr_runtime_list finds simxr

The expected pixels come from hello_xr's own scene (src/tests/hello_xr in OpenXR-SDK-Source
1.0.20: clear colour DarkSlateGray, faces of pure red/green/blue, a 25 cm cube 2 m in front of
the head, hand cubes of 10 cm scaled by 1 - grab/2), not from simxr's code.
"""

import os
import re
import shutil
import struct
import subprocess
import sys
import threading
import zlib
from pathlib import Path

HELLO_XR = "/usr/bin/hello_xr"
RUNTIME_LIST = "/usr/bin/openxr_runtime_list"
VALIDATION_LAYER = "XR_APILAYER_LUNARG_core_validation"
TIMEOUT_S = 120
SIZE = 256  # per-eye pixels of the test display (small: the PNGs are decoded in pure Python)
RATE_HZ = 90

# A 90-degree symmetric display, so pixel (x, y) of an eye looks along tan = (2x/SIZE - 1).
DISPLAY = f"""name = "hello_xr test display"
ipd = 0.064
width = {SIZE}
height = {SIZE}
[left]
tan_left = -1.0
tan_right = 1.0
tan_up = 1.0
tan_down = -1.0
[right]
tan_left = -1.0
tan_right = 1.0
tan_up = 1.0
tan_down = -1.0
"""

# The scripted squeeze of the grab scenario, seconds (predicted display time of frame n: n / 90).
PRESS_START, PRESS_END = 0.5, 0.8


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def srgb_byte(linear):
    """The byte an sRGB swapchain stores for a linear value (IEC 61966-2-1)."""
    encoded = linear * 12.92 if linear <= 0.0031308 else 1.055 * linear ** (1 / 2.4) - 0.055
    return round(255 * encoded)


# hello_xr clears to DarkSlateGray given as linear floats; simxr offers R8G8B8A8_SRGB first and
# dumps the stored bytes, so the background reads as their sRGB encoding.
BACKGROUND = tuple(srgb_byte(v) for v in (0.184313729, 0.309803933, 0.309803933))
RED, GREEN, BLUE = (255, 0, 0), (0, 255, 0), (0, 0, 255)


def read_png(path):
    """(width, height, rows of RGB tuples) of an 8-bit RGBA, non-interlaced PNG."""
    data = path.read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail(f"{path} is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos : pos + 4])
        kind = data[pos + 4 : pos + 8]
        body = data[pos + 8 : pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type != 6 or interlace != 0:
        fail(f"{path}: expected 8-bit RGBA, got depth {depth} colour type {colour_type}")
    raw = zlib.decompress(idat)
    stride = width * 4
    previous = bytearray(stride)
    rows = []
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        line = bytearray(raw[start + 1 : start + 1 + stride])
        # PNG spec 9.2: undo the row's filter.
        if kind == 1:
            for i in range(4, stride):
                line[i] = (line[i] + line[i - 4]) & 0xFF
        elif kind == 2:
            for i in range(stride):
                line[i] = (line[i] + previous[i]) & 0xFF
        elif kind == 3:
            for i in range(stride):
                left = line[i - 4] if i >= 4 else 0
                line[i] = (line[i] + (left + previous[i]) // 2) & 0xFF
        elif kind == 4:
            for i in range(stride):
                a = line[i - 4] if i >= 4 else 0
                b = previous[i]
                c = previous[i - 4] if i >= 4 else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + predictor) & 0xFF
        rows.append([tuple(line[i : i + 3]) for i in range(0, stride, 4)])
        previous = line
    return width, height, rows


def near(colour, expected, tolerance=2):
    return all(abs(a - b) <= tolerance for a, b in zip(colour, expected))


def count(rows, expected, x_range=None, y_range=None):
    xs = x_range or range(len(rows[0]))
    ys = y_range or range(len(rows))
    return sum(1 for y in ys for x in xs if near(rows[y][x], expected))


def foreground(rows, x_range, y_range):
    """Pixels that are not the background: what hello_xr drew there."""
    return sum(1 for y in y_range for x in x_range if not near(rows[y][x], BACKGROUND))


def run_hello_xr(manifest, work, script_text):
    if not os.access(HELLO_XR, os.X_OK):
        fail(f"{HELLO_XR} is not installed: it comes with the Debian package libopenxr-utils "
             "(scripts/install-deps.sh installs it)")
    layers = Path("/usr/share/openxr/1/api_layers/explicit.d")
    if not any(VALIDATION_LAYER in p.read_text() for p in layers.glob("*.json")):
        fail(f"the OpenXR layer {VALIDATION_LAYER} is not installed: it comes with the Debian "
             "package openxr-layer-corevalidation (scripts/install-deps.sh installs it)")
    if work.exists():
        shutil.rmtree(work)
    (work / "frames").mkdir(parents=True)
    (work / "display.toml").write_text(DISPLAY)
    (work / "session.toml").write_text(script_text)
    env = dict(os.environ)
    env.update({
        "XR_RUNTIME_JSON": str(manifest),
        "SIMXR_SCRIPT": str(work / "session.toml"),
        # OpenXR's own validation of every call hello_xr makes (and simxr answers).
        "XR_ENABLE_API_LAYERS": VALIDATION_LAYER,
    })
    # hello_xr ends its loop when a key is read from stdin (getchar() in a thread); at end of
    # file it would stop at once and exit 0 without a session. stdin is a pipe kept open and
    # never written, so only the runtime's STOPPING/EXITING can end the session.
    process = subprocess.Popen([HELLO_XR, "-g", "Vulkan2", "-v"], stdin=subprocess.PIPE,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                               cwd=work)
    try:
        output = wait_keeping_stdin_open(process)
    except subprocess.TimeoutExpired:
        process.kill()
        fail(f"hello_xr did not exit within {TIMEOUT_S} s (exit_after_s should have stopped it)")
    (work / "hello_xr.log").write_text(output)
    if process.returncode != 0:
        print(output[-6000:])
        fail(f"hello_xr exited with {process.returncode} (log: {work / 'hello_xr.log'})")
    return output


def wait_keeping_stdin_open(process):
    """Reads hello_xr's output until it exits; its stdin stays open (and empty) meanwhile."""
    chunks = []
    reader = threading.Thread(target=lambda: chunks.append(process.stdout.read()))
    reader.start()
    process.wait(timeout=TIMEOUT_S)
    reader.join()
    process.stdin.close()
    return chunks[0].decode(errors="replace")


def check_log(output, log_path):
    # The session went the whole way and was ended by the runtime (spec 9.3): STOPPING, then
    # EXITING after xrEndSession. hello_xr logs each state it receives.
    states = re.findall(r"XrEventDataSessionStateChanged: state \w+->(XR_SESSION_STATE_\w+)",
                        output)
    for state in ("READY", "SYNCHRONIZED", "VISIBLE", "FOCUSED", "STOPPING", "EXITING"):
        if "XR_SESSION_STATE_" + state not in states:
            fail(f"hello_xr never reached {state} (states: {states}; log: {log_path})")
    if states[-1] != "XR_SESSION_STATE_EXITING":
        fail(f"the last state was {states[-1]}, not EXITING")
    # hello_xr logs its own failures, Vulkan validation errors (simxr records commands on its
    # device) at level Error; the OpenXR validation layer writes VALID_ERROR.
    errors = [line for line in output.splitlines()
              if "][Error" in line or "VALID_ERROR" in line]
    if errors:
        fail("errors in hello_xr's output:\n" + "\n".join(errors[:20]))
    # hello_xr prints "nothing" for an action without bound sources.
    for action in ("Grab", "Quit", "Pose", "Vibrate"):
        line = re.search(action + r" action is bound to (.*)", output)
        if line is None or line.group(1).strip() == "nothing":
            fail(f"hello_xr's {action} action is not bound")


def dumped_frames(work):
    frames = {}
    for png in sorted((work / "frames").glob("frame_*_left.png")):
        n = int(re.match(r"frame_(\d+)_left", png.name).group(1))
        right = png.with_name(png.name.replace("_left", "_right"))
        if not right.exists():
            fail(f"{png.name} has no right eye")
        frames[n] = (png, right)
    if not frames:
        fail("simxr dumped no frames")
    return frames


def check_scene(manifest, work):
    output = run_hello_xr(manifest, work, f"""hmd = "display.toml"
display_rate_hz = {RATE_HZ}
exit_after_s = 1.0
dump_dir = "frames"
dump_every = 30
""")
    check_log(output, work / "hello_xr.log")
    centre = range(SIZE // 2 - 2, SIZE // 2 + 2)
    lower = range(SIZE // 2, SIZE)
    for n, eyes in dumped_frames(work).items():
        images = []
        for png in eyes:
            width, height, rows = read_png(png)
            if (width, height) != (SIZE, SIZE):
                fail(f"{png.name} is {width}x{height}, the display is {SIZE}x{SIZE}")
            colours = {c for row in rows for c in row}
            if len(colours) < 2:
                fail(f"{png.name} is blank (one colour)")
            histogram = {}
            for row in rows:
                for c in row:
                    histogram[c] = histogram.get(c, 0) + 1
            most = max(histogram, key=histogram.get)
            if not near(most, BACKGROUND):
                fail(f"{png.name}: background {most}, hello_xr clears to {BACKGROUND} (sRGB)")
            # The "ViewFront" cube: 25 cm, 2 m straight ahead of the head, its blue +z face
            # towards the viewer; ipd/2 shifts it by 128 * 0.032 / 1.875 = 2 pixels per eye, its
            # face spans 128 * 0.125 / 1.875 = 8.5 pixels either side of the centre.
            if count(rows, BLUE, centre, centre) != len(centre) ** 2:
                fail(f"{png.name}: the centre is not the blue face of hello_xr's ViewFront cube")
            # The hand cubes (action spaces, held below the eyes) show their green top and a red
            # side; nothing else of the scene is in the lower half with these colours in this
            # amount: at least a quarter of the 10 cm cube's 36-pixel-wide top.
            for name, colour in (("green", GREEN), ("red", RED)):
                if count(rows, colour, None, lower) < 100:
                    fail(f"{png.name}: no {name} cube face in the lower half (hand cubes)")
            images.append(rows)
        if images[0] == images[1]:
            fail(f"frame {n}: both eyes are identical (no stereo)")
    print(f"hello_xr scene: {len(dumped_frames(work))} frame pairs checked")


def check_grab(manifest, work):
    output = run_hello_xr(manifest, work, f"""hmd = "display.toml"
display_rate_hz = {RATE_HZ}
interaction_profile = "/interaction_profiles/microsoft/motion_controller"
exit_after_s = 1.0
dump_dir = "frames"
dump_every = 10
[[input]]
t = {PRESS_START}
path = "/user/hand/right/input/squeeze/click"
duration = {PRESS_END - PRESS_START}
""")
    check_log(output, work / "hello_xr.log")
    if "Microsoft Mixed Reality Motion Controller" not in output:
        fail("hello_xr's actions are not bound to the motion controller")
    # hello_xr reads actions before it waits for the frame it renders, so a frame shows the
    # press state at its own or the previous frame's time: only frames where both agree count.
    def pressed(t):
        return PRESS_START <= t < PRESS_END

    left_half, right_half = range(0, SIZE // 2), range(SIZE // 2, SIZE)
    lower = range(SIZE // 2, SIZE)
    counts = {True: [], False: []}
    left_counts = []
    for n, (png, _) in dumped_frames(work).items():
        now, before = pressed(n / RATE_HZ), pressed((n - 1) / RATE_HZ)
        if now != before:
            continue
        _, _, rows = read_png(png)
        counts[now].append(foreground(rows, right_half, lower))
        left_counts.append(foreground(rows, left_half, lower))
    if not counts[True] or not counts[False]:
        fail(f"no dumped frame inside and outside the press: {sorted(dumped_frames(work))}")
    # Squeezed fully, the right cube is half as wide: a quarter of its area. The rest of the
    # quadrant (a stage cube) is the same in every frame, as the head does not move.
    if max(counts[True]) >= 0.6 * min(counts[False]):
        fail(f"the right hand cube did not shrink while squeezed: drawn pixels {counts}")
    if max(left_counts) - min(left_counts) > 0.02 * max(left_counts):
        fail(f"the left hand cube changed without a press: {left_counts}")
    print(f"hello_xr grab: right quadrant pixels pressed {counts[True]}, released {counts[False]}")


def check_runtime_list(manifest, work):
    if not os.access(RUNTIME_LIST, os.X_OK):
        fail(f"{RUNTIME_LIST} is not installed: it comes with the Debian package libopenxr-utils "
             "(scripts/install-deps.sh installs it)")
    work.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ)
    env["XR_RUNTIME_JSON"] = str(manifest)
    env.pop("SIMXR_SCRIPT", None)
    result = subprocess.run([RUNTIME_LIST], stdin=subprocess.DEVNULL, capture_output=True,
                            text=True, env=env, cwd=work, timeout=TIMEOUT_S)
    output = result.stdout + result.stderr
    if result.returncode != 0:
        fail(f"openxr_runtime_list exited with {result.returncode}:\n{output}")
    # It creates an instance and prints the HMD system's name, which simxr starts with its own.
    if not re.search(r"systemName: monoplane simxr", output):
        fail(f"openxr_runtime_list does not name monoplane simxr:\n{output}")
    # The extension simxr must offer for any Vulkan application (docs/simxr.md).
    if not re.search(r"^\s*XR_KHR_vulkan_enable2 \d+$", output, re.MULTILINE):
        fail(f"openxr_runtime_list does not list XR_KHR_vulkan_enable2:\n{output}")
    print(output)


def main():
    checks = {"scene": check_scene, "grab": check_grab, "runtime_list": check_runtime_list}
    if len(sys.argv) != 4 or sys.argv[3] not in checks:
        fail("usage: hello_xr_test.py MANIFEST WORK_DIR " + "|".join(checks))
    manifest, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve()
    if not manifest.exists():
        fail(f"no simxr manifest at {manifest} (build monoplane_simxr)")
    checks[sys.argv[3]](manifest, work)


if __name__ == "__main__":
    main()
