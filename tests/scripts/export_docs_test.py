#!/usr/bin/env python3
"""docs/data.md's pandas and R snippets, run verbatim against a real export (issue 17, item 6).

    export_docs_test.py --monoplane build/monoplane --source . --part pandas|r-csv|r-json-db

Builds a study database with the real CLI (protocols/demo.toml, simulated observer): session 1
runs to the end, session 2 is killed after its third decision, so the export holds practice
trials, data trials and undecided trials (NA outcomes); a third participant's session runs on the
simulated headset with eye gaze recorded (a protocol with [gaze] record = true), so the trial
export's gaze columns hold values beside NA. Exports it as CSV and JSON (and a note as notes-csv,
the gaze as gaze-csv), checks that the trials, notes and gaze CSV columns are the ones
docs/data.md's tables list, in order, and runs one snippet of docs/data.md in that folder (the
database as study.db):

  pandas     the ```python block under "### pandas", with Debian's /usr/bin/python3 (the
             python3-pandas package is for it, not for a pyenv python3 on PATH);
  r-csv      the first ```r block under "### R" (base R only: read.csv);
  r-json-db  the second ```r block (jsonlite, DBI, RSQLite).

The snippet's output must show the values counted here independently (Python's csv module over
the CSV, sqlite3 over the database): the number of decided data trials, the choice rate per scene
and distance, the number of events; then a check appended to the snippet, in the same
interpreter, reports the types and NA counts of what the snippet read, and of gaze.csv and the
trials' gaze columns read as the snippet reads the trials (counted here from the CSV and the
database). Exits 77 (CTest's SKIP_RETURN_CODE) with a message when the interpreter or a package
the part needs is absent.
"""
import argparse
import csv
import json
import math
import os
import re
import shutil
import signal
import sqlite3
import subprocess
import sys
import tempfile

SKIP = 77
SCENES = ["beams", "landscape", "spheres"]
# The gaze session: one scene at two distances, no practice, gaze recorded; simxr's eyes rest on a
# point straight ahead and blink every second.
GAZE_PROTOCOL = """name = "gaze"
scenes = ["spheres"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
practice_trials = 0

[gaze]
record = true
"""
GAZE_SCRIPT = """hmd = "vive"
display_rate_hz = 10
[gaze]
blink_every_s = 1
blink_s = 0.15
[[fixation]]
t = 0
duration = 1000
target = [0.0, 1.6, -10.0]
"""


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def skip(message):
    print("SKIP: " + message)
    sys.exit(SKIP)


def snippets(docs_path, heading, language):
    """The fenced ```language blocks between `heading` and the next heading, verbatim."""
    with open(docs_path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    blocks, inside, current, block = [], False, None, None
    for line in lines:
        if block is not None:
            if line.strip() == "```":
                blocks.append("\n".join(block) + "\n")
                block = None
            else:
                block.append(line)
            continue
        if line.startswith("#"):
            inside = line.strip() == heading
        elif inside and line.strip() == "```" + language:
            block = []
    if not blocks:
        fail("%s has no ```%s block under '%s'" % (docs_path, language, heading))
    return blocks


def run_cli(args, what):
    done = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        fail("%s failed (%d):\n%s%s" % (what, done.returncode, done.stdout, done.stderr))


def make_study(monoplane, protocol, folder):
    db = os.path.join(folder, "study.db")
    common = ["--protocol", protocol, "--db", db, "--headset", "none", "--observer", "default",
              "--window", "off"]
    run_cli([monoplane, "study", "run", "--participant", "P01", "--seed", "3"] + common,
            "study run P01")
    # Session 2: killed (SIGKILL) while it sleeps after its third recorded outcome.
    child = subprocess.Popen([monoplane, "study", "run", "--participant", "P02", "--seed", "4",
                              "--trace", "--pace-ms", "150"] + common,
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    outcomes = 0
    for line in child.stdout:
        if " outcome " in line:
            outcomes += 1
            if outcomes == 3:
                child.send_signal(signal.SIGKILL)
                break
    child.stdout.close()
    child.wait()
    if outcomes != 3:
        fail("study run P02 ended after %d outcomes, before the third" % outcomes)
    run_gaze_session(monoplane, db, folder)
    check_roster_gaze(monoplane, db)
    run_cli([monoplane, "study", "export", "--db", db, "--format", "csv", "--out",
             os.path.join(folder, "trials.csv")], "study export --format csv")
    run_cli([monoplane, "study", "export", "--db", db, "--format", "json", "--out",
             os.path.join(folder, "trials.json")], "study export --format json")
    run_cli([monoplane, "study", "note", "--db", db, "--participant", "P01", "checked"],
            "study note")
    run_cli([monoplane, "study", "export", "--db", db, "--format", "notes-csv", "--out",
             os.path.join(folder, "notes.csv")], "study export --format notes-csv")
    run_cli([monoplane, "study", "export", "--db", db, "--format", "gaze-csv", "--out",
             os.path.join(folder, "gaze.csv")], "study export --format gaze-csv")


def run_gaze_session(monoplane, db, folder):
    """P03's session on the simulated headset, recording gaze."""
    protocol = os.path.join(folder, "gaze.toml")
    script = os.path.join(folder, "script.toml")
    with open(protocol, "w", encoding="utf-8") as f:
        f.write(GAZE_PROTOCOL)
    with open(script, "w", encoding="utf-8") as f:
        f.write(GAZE_SCRIPT)
    run_cli([monoplane, "study", "run", "--protocol", protocol, "--db", db, "--participant",
             "P03", "--seed", "5", "--headset", "simulated", "--observer", "default",
             "--sim-script", script, "--window", "off", "--detail", "test",
             "--resolution-scale", "0.1", "--neutral-s", "0.3"], "study run P03 (gaze)")


def check_roster_gaze(monoplane, db):
    """`study list --json` flags the session that holds gaze, and only it."""
    done = subprocess.run([monoplane, "study", "list", "--db", db, "--json"],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        fail("study list failed (%d):\n%s" % (done.returncode, done.stderr))
    flags = {s["participant"]: s["gaze"] for s in json.loads(done.stdout)["sessions"]}
    if flags != {"P01": False, "P02": False, "P03": True}:
        fail("study list --json: gaze %s, expected only P03's session" % flags)


def documented_columns(docs_path, heading, first_column):
    """The backquoted names in the first cell of the table under `heading` that starts with a
    row for `first_column`, in order."""
    with open(docs_path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    inside, names = False, []
    for line in lines:
        if line.startswith("#"):
            if names:
                break
            inside = line.strip() == heading
        elif inside and line.startswith("| `"):
            name = line.split("`")[1]
            if not names and name != first_column:
                continue
            names.append(name)
        elif inside and names and not line.startswith("|"):
            break
    return names


def csv_header(path):
    with open(path, newline="", encoding="utf-8") as f:
        return next(csv.reader(f))


def check_documented_columns(docs, folder):
    """The columns the trials and notes exports write are docs/data.md's tables, in order."""
    trials = csv_header(os.path.join(folder, "trials.csv"))
    documented = documented_columns(docs, "## Export", "participant")
    want = [c for c in trials if not c.startswith("var_")] + ["var_<name>"]
    if documented != want:
        fail("trials.csv has the columns %s; docs/data.md's table under '## Export' lists %s"
             % (want, documented))
    for name, paragraph in (("notes.csv", "**Notes**"), ("gaze.csv", "**Gaze**")):
        written = csv_header(os.path.join(folder, name))
        documented = paragraph_columns(docs, paragraph)
        if documented != written:
            fail("%s has the columns %s; docs/data.md's table after '%s' lists %s"
                 % (name, written, paragraph, documented))


def paragraph_columns(docs_path, paragraph):
    """The columns of the table right after the paragraph that begins with `paragraph`; a row
    naming several (`a`, `b`) stands for each."""
    with open(docs_path, encoding="utf-8") as f:
        text = f.read()
    start = text.find(paragraph)
    if start < 0:
        fail("docs/data.md has no '%s' paragraph" % paragraph)
    names = []
    for line in text[start:].split("\n"):
        if line.startswith("| `"):
            names.extend(re.findall(r"`([^`]+)`", line.split("|")[1]))
        elif names:
            break
    return names


def expected_values(folder):
    """What the snippets must find, counted without pandas or R."""
    with open(os.path.join(folder, "trials.csv"), newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for column in ("practice", "decided"):
            if row[column] not in ("TRUE", "FALSE"):
                fail("trials.csv: %s is '%s', not TRUE or FALSE" % (column, row[column]))
    data = [r for r in rows if r["practice"] == "FALSE" and r["decided"] == "TRUE"]
    cells = {}
    for r in data:
        cells.setdefault((r["scene"], float(r["mono_plane"])), []).append(
            r["chosen_mode"] == "stereo")
    rates = {key: sum(v) / len(v) for key, v in cells.items()}
    con = sqlite3.connect("file:%s?mode=ro" % os.path.join(folder, "study.db"), uri=True)
    db_data = con.execute("SELECT COUNT(*) FROM trials WHERE practice = 0 AND decided = 1"
                          ).fetchone()[0]
    events = con.execute("SELECT COUNT(*) FROM events WHERE session_id = 1").fetchone()[0]
    undecided = con.execute("SELECT COUNT(*) FROM trials WHERE decided = 0").fetchone()[0]
    practice = con.execute("SELECT COUNT(*) FROM trials WHERE practice = 1").fetchone()[0]
    con.close()
    if db_data != len(data):
        fail("the CSV has %d decided data trials, the database %d" % (len(data), db_data))
    # The fixture must exercise both filters and the NA fields.
    if undecided == 0 or practice == 0 or len(data) == 0 or events == 0:
        fail("the study has %d undecided, %d practice, %d data trials and %d events; each must "
             "be > 0" % (undecided, practice, len(data), events))
    return {
        "rows": len(rows), "data": len(data), "stereo": sum(r["chosen_mode"] == "stereo"
                                                           for r in data),
        "practice": practice, "undecided": undecided, "events": events, "rates": rates,
    }


GAZE_COLUMNS = ["gaze_samples", "gaze_share_beyond_m", "gaze_error_mean_arcmin_1",
                "gaze_error_mean_arcmin_2", "gaze_error_max_arcmin_1", "gaze_error_max_arcmin_2",
                "gaze_fixations"]


def read_rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def check_gaze_rows(gaze, samples):
    """gaze.csv: a row per frame with a sample; its angles are its direction's."""
    if len(gaze) != samples:
        fail("gaze.csv has %d rows, the database %d frames with gaze" % (len(gaze), samples))
    for r in gaze:
        if r["gaze_valid"] not in ("TRUE", "FALSE") or r["gaze_at_sky"] not in ("TRUE", "FALSE",
                                                                               "NA"):
            fail("gaze.csv: gaze_valid '%s', gaze_at_sky '%s'" % (r["gaze_valid"],
                                                                   r["gaze_at_sky"]))
        if r["gaze_valid"] == "FALSE":
            if r["gaze_yaw_deg"] != "NA":
                fail("gaze.csv: an invalid sample has an angle: %s" % r)
            continue
        x, y, z = (float(r["gaze_dir_" + axis]) for axis in "xyz")
        for column, want in (("gaze_yaw_deg", math.atan2(x, -z)),
                             ("gaze_pitch_deg", math.atan2(y, math.hypot(x, z))),
                             ("gaze_eccentricity_deg", math.acos(max(-1.0, min(1.0, -z))))):
            # acos loses about 1e-8 rad near the axis: a tolerance of 1e-5 degrees.
            if not math.isclose(float(r[column]), math.degrees(want), abs_tol=1e-5):
                fail("gaze.csv: %s %s, its direction says %s" % (column, r[column],
                                                                 math.degrees(want)))


def expected_fixations(frames):
    """I-DT's count where the gaze stays within 1 degree: the runs of valid samples on a label
    screen at least 0.1 s long (a blink or another screen ends a run)."""
    runs, run = [], []
    for valid, label, time_ns, x, y, z in frames:
        if valid == 1 and label:
            run.append((time_ns, math.degrees(math.atan2(x, -z)),
                        math.degrees(math.atan2(y, math.hypot(x, z)))))
            continue
        runs.append(run)
        run = []
    runs.append(run)
    count = 0
    for run in runs:
        if not run or run[-1][0] - run[0][0] < 100000000:
            continue
        spread = [max(a) - min(a) for a in zip(*[(h, v) for _, h, v in run])]
        if sum(spread) > 1.0:
            fail("the simulated gaze wanders %s degrees in a run: not one fixation" % spread)
        count += 1
    return count


def gaze_in_database(con, session, trial):
    """One trial's gaze columns, worked out by SQL over its frames."""
    label = "shown IN ('label1', 'label2')"
    where = "session_id = %d AND trial_index = %d AND gaze_valid = 1 AND " % (session, trial)
    samples = con.execute("SELECT COUNT(*) FROM frames WHERE " + where + label).fetchone()[0]
    share = con.execute("SELECT AVG(gaze_depth_m IS NULL OR gaze_depth_m > gaze_mono_plane_m) "
                        "FROM frames WHERE " + where + label +
                        " AND gaze_error_arcmin IS NOT NULL").fetchone()[0]
    errors = [con.execute("SELECT AVG(gaze_error_arcmin), MAX(gaze_error_arcmin) FROM frames "
                          "WHERE " + where + "shown = ?", (shown,)).fetchone()
              for shown in ("label1", "label2")]
    frames = con.execute("SELECT gaze_valid, shown IN ('label1', 'label2'), display_time_ns, "
                         "gaze_dir_x, gaze_dir_y, gaze_dir_z FROM frames WHERE session_id = ? "
                         "AND trial_index = ? ORDER BY frame",
                         (session, trial)).fetchall()
    return [samples, share, errors[0][0], errors[1][0], errors[0][1], errors[1][1],
            expected_fixations(frames)]


def expected_gaze(folder):
    """What gaze.csv and the trials' gaze columns hold, counted without pandas or R: the CSVs with
    Python's csv module, the gaze summaries by SQL over the database."""
    gaze = read_rows(os.path.join(folder, "gaze.csv"))
    trials = read_rows(os.path.join(folder, "trials.csv"))
    con = sqlite3.connect("file:%s?mode=ro" % os.path.join(folder, "study.db"), uri=True)
    check_gaze_rows(gaze, con.execute("SELECT COUNT(*) FROM frames WHERE gaze_valid IS NOT NULL"
                                      ).fetchone()[0])
    with_gaze = 0
    for r in trials:
        got = [None if r[c] == "NA" else float(r[c]) for c in GAZE_COLUMNS]
        want = [None] * len(GAZE_COLUMNS)
        if r["participant"] == "P03":
            want = gaze_in_database(con, int(r["session_id"]), int(r["trial_index"]))
            with_gaze += 1
        for column, g, w in zip(GAZE_COLUMNS, got, want):
            if (g is None) != (w is None) or (g is not None and not math.isclose(g, w,
                                                                                  rel_tol=1e-9)):
                fail("trials.csv: trial %s of %s: %s is %s, the database says %s"
                     % (r["trial_index"], r["participant"], column, r[column], w))
    con.close()
    invalid = sum(r["gaze_valid"] == "FALSE" for r in gaze)
    samples = sum(int(r["gaze_samples"]) for r in trials if r["gaze_samples"] != "NA")
    fixations = sum(int(r["gaze_fixations"]) for r in trials if r["gaze_fixations"] != "NA")
    at_sky_na = sum(r["gaze_at_sky"] == "NA" for r in gaze)
    # The fixture must exercise both: samples and blinks, trials with gaze and without, samples
    # with a gaze point and without.
    if invalid == 0 or invalid == len(gaze) or with_gaze == 0 or with_gaze == len(trials) or \
            samples == 0 or fixations == 0 or at_sky_na == 0 or at_sky_na == len(gaze):
        fail("the gaze fixture has %d invalid of %d samples, %d of %d trials with gaze, %d label "
             "samples, %d fixations, %d samples without a point" % (
                 invalid, len(gaze), with_gaze, len(trials), samples, fixations, at_sky_na))
    return {"gaze_rows": len(gaze), "gaze_invalid": invalid, "trials_no_gaze":
            len(trials) - with_gaze, "gaze_samples": samples}


def run_snippet(command, suffix, code, folder):
    path = os.path.join(folder, "snippet" + suffix)
    with open(path, "w", encoding="utf-8") as f:
        f.write(code)
    done = subprocess.run(command + [path], cwd=folder, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    print(done.stdout)
    if done.returncode != 0:
        fail("the snippet failed (%d):\n%s" % (done.returncode, code))
    return done.stdout


def check_line(output, tag):
    """The fields of the line 'tag ...' the appended check printed."""
    for line in output.split("\n"):
        if line.startswith(tag + " "):
            return line.split()[1:]
    fail("no '%s' line in the output" % tag)


def expect(what, got, want):
    if str(got) != str(want):
        fail("%s: %s, expected %s" % (what, got, want))


def expect_printed(output, pattern, want, what):
    found = re.search(pattern, output, re.MULTILINE)
    if not found:
        fail("the snippet did not print %s" % what)
    expect(what, found.group(1), want)


def compare_rates(table, want, what):
    if set(table) != set(want):
        fail("%s: cells %s, expected %s" % (what, sorted(table), sorted(want)))
    for key, rate in want.items():
        if not math.isclose(table[key], rate, abs_tol=1e-5):
            fail("%s: %s rate %s, expected %s" % (what, key, table[key], rate))


def pandas_rates(output):
    """The scene x mono_plane table print(... .unstack("scene")) shows (NaN: no trials)."""
    lines = output.split("\n")
    for i, line in enumerate(lines):
        if line.split()[:1] == ["scene"]:
            scenes = line.split()[1:]
            table = {}
            for row in lines[i + 1:]:
                fields = row.split()
                if len(fields) != len(scenes) + 1:
                    continue
                try:
                    values = [float(v) for v in fields]
                except ValueError:
                    break
                for scene, value in zip(scenes, values[1:]):
                    if not math.isnan(value):
                        table[(scene, values[0])] = value
            return table
    fail("the snippet did not print the scene x mono_plane table")


def r_rates(output):
    """The rows 'n scene mono_plane chose_stereo' that aggregate() prints."""
    table = {}
    for scene, plane, rate in re.findall(r"^\s*\d+\s+(\w+)\s+([-\d.]+)\s+([-\d.]+)\s*$", output,
                                         re.MULTILINE):
        table[(scene, float(plane))] = float(rate)
    return table


def part_pandas(docs, folder, want):
    python = "/usr/bin/python3"  # Debian's python3-pandas is for Debian's interpreter
    if not os.access(python, os.X_OK):
        skip("%s is absent (apt-get install python3-pandas)" % python)
    if subprocess.run([python, "-c", "import pandas"], stderr=subprocess.DEVNULL).returncode:
        skip("pandas is not installed for %s (apt-get install python3-pandas)" % python)
    code = snippets(docs, "### pandas", "python")[0]
    check = ('print("CHECK", len(df), len(data), int(data.chose_stereo.sum()), '
             'int(df.block.isna().sum()), int(df.valid.isna().sum()), '
             'int(df.observer.isna().sum()), df.practice.dtype, df.decided.dtype, '
             'df.valid.dtype, ",".join(sorted({type(v).__name__ for v in df.valid.dropna()})), '
             'len(js), js.practice.dtype, '
             'int(js.valid.isna().sum()), len(events))\n')
    gaze_check = ('gz = pd.read_csv("gaze.csv")\n'
                  'print("GAZE", len(gz), gz.gaze_valid.dtype, int(gz.gaze_yaw_deg.isna().sum()), '
                  'gz.gaze_yaw_deg.dtype, gz.gaze_at_sky.dtype, '
                  '",".join(sorted({type(v).__name__ for v in gz.gaze_at_sky.dropna()})), '
                  'int(df.gaze_samples.isna().sum()), int(df.gaze_samples.sum()), '
                  'df.gaze_share_beyond_m.dtype, int(js.gaze_samples.isna().sum()))\n')
    output = run_snippet([python], ".py", code + check + gaze_check, folder)
    expect_printed(output, r"^(\d+) decided data trials$", want["data"], "decided data trials")
    expect_printed(output, r"^(\d+) events in session 1$", want["events"], "events in session 1")
    compare_rates(pandas_rates(output), want["rates"], "pandas choice rates")
    expect("pandas gaze: gaze.csv rows, gaze_valid dtype, NA yaw, yaw dtype, gaze_at_sky dtype, "
           "types of its values, NA gaze_samples, their sum, gaze_share_beyond_m dtype, "
           "JSON NA gaze_samples",
           " ".join(check_line(output, "GAZE")),
           "%d bool %d float64 object bool %d %d float64 %d" % (
               want["gaze_rows"], want["gaze_invalid"], want["trials_no_gaze"],
               want["gaze_samples"], want["trials_no_gaze"]))
    expect("pandas: rows, data trials, stereo choices, NA blocks, NA valid, NA observers, "
           "practice dtype, decided dtype, valid dtype, types of the valid values, JSON rows, "
           "JSON practice dtype, JSON NA valid, events",
           " ".join(check_line(output, "CHECK")),
           "%d %d %d %d %d 0 bool bool object bool %d bool %d %d" % (
               want["rows"], want["data"], want["stereo"], want["practice"], want["undecided"],
               want["rows"], want["undecided"], want["events"]))


def rscript():
    found = shutil.which("Rscript")
    if not found:
        skip("Rscript is absent (apt-get install r-base-core)")
    return found


def part_r_csv(docs, folder, want):
    command = [rscript(), "--vanilla"]
    code = snippets(docs, "### R", "r")[0]
    check = ('cat("CHECK", nrow(df), nrow(data), sum(data$chose_stereo), sum(is.na(df$block)), '
             'sum(is.na(df$valid)), sum(is.na(df$observer)), class(df$practice), '
             'class(df$decided), class(df$valid), class(df$block), class(df$participant), '
             '"\\n")\n')
    gaze_check = ('gz <- read.csv("gaze.csv")\n'
                  'cat("GAZE", nrow(gz), class(gz$gaze_valid), sum(is.na(gz$gaze_yaw_deg)), '
                  'is.numeric(gz$gaze_yaw_deg), class(gz$gaze_at_sky), '
                  'sum(is.na(df$gaze_samples)), sum(df$gaze_samples, na.rm = TRUE), '
                  'class(df$gaze_samples), is.numeric(df$gaze_share_beyond_m), "\\n")\n')
    output = run_snippet(command, ".R", code + check + gaze_check, folder)
    expect_printed(output, r"^(\d+) decided data trials$", want["data"], "decided data trials")
    compare_rates(r_rates(output), want["rates"], "R choice rates")
    expect("R gaze: gaze.csv rows, gaze_valid class, NA yaw, yaw numeric, gaze_at_sky class, NA "
           "gaze_samples, their sum, their class, gaze_share_beyond_m numeric",
           " ".join(check_line(output, "GAZE")),
           "%d logical %d TRUE logical %d %d integer TRUE" % (
               want["gaze_rows"], want["gaze_invalid"], want["trials_no_gaze"],
               want["gaze_samples"]))
    expect("R: rows, data trials, stereo choices, NA blocks, NA valid, NA observers, classes of "
           "practice decided valid block participant",
           " ".join(check_line(output, "CHECK")),
           "%d %d %d %d %d 0 logical logical logical integer character" % (
               want["rows"], want["data"], want["stereo"], want["practice"], want["undecided"]))


def part_r_json_db(docs, folder, want):
    command = [rscript(), "--vanilla"]
    missing = subprocess.run(
        command + ["-e", 'p <- c("jsonlite", "DBI", "RSQLite"); '
                   'cat(p[!sapply(p, requireNamespace, quietly = TRUE)])'],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout.split()
    if missing:
        skip("R packages %s are absent (apt-get install r-cran-jsonlite r-cran-dbi "
             "r-cran-rsqlite)" % " ".join(missing))
    code = snippets(docs, "### R", "r")[1]
    check = ('cat("CHECK", nrow(js), class(js$practice), sum(is.na(js$valid)), '
             'sum(is.na(js$block)), nrow(events), sum(is.na(js$gaze_samples)), '
             'sum(js$gaze_samples, na.rm = TRUE), "\\n")\n')
    output = run_snippet(command, ".R", code + check, folder)
    expect_printed(output, r"^(\d+) events in session 1$", want["events"], "events in session 1")
    expect("R JSON and database: JSON rows, practice class, NA valid, NA blocks, events, NA "
           "gaze_samples, their sum",
           " ".join(check_line(output, "CHECK")),
           "%d logical %d %d %d %d %d" % (want["rows"], want["undecided"], want["practice"],
                                          want["events"], want["trials_no_gaze"],
                                          want["gaze_samples"]))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--monoplane", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--part", required=True, choices=["pandas", "r-csv", "r-json-db"])
    args = parser.parse_args()
    docs = os.path.join(args.source, "docs", "data.md")
    parts = {"pandas": part_pandas, "r-csv": part_r_csv, "r-json-db": part_r_json_db}
    folder = tempfile.mkdtemp(prefix="export_docs_")
    try:
        make_study(os.path.abspath(args.monoplane),
                   os.path.join(args.source, "protocols", "demo.toml"), folder)
        want = expected_values(folder)
        want.update(expected_gaze(folder))
        check_documented_columns(docs, folder)
        parts[args.part](docs, folder, want)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    print("PASS: docs/data.md %s snippet" % args.part)


if __name__ == "__main__":
    main()
