#!/usr/bin/env python3
"""Formula-like text in CSV exports and the way back (docs/data.md, "Text that looks like a
formula").

    csv_injection_test.py --monoplane build/monoplane --source . --part pandas|r

Runs a headless session of protocols/demo.toml with a text participant variable, stores tricky
notes with `monoplane study note` (=1+1, -5 dB, @home, a,"b" with a line break, ...), exports
the notes and the trials as CSV and checks:
  - in the raw CSV (Python's csv module), every text that begins with =, +, -, @, tab or CR
    after any apostrophes carries one more leading apostrophe, and nothing else does;
  - the docs' snippet for the part (the ```python or the ```r block under that heading, run
    verbatim with Debian's /usr/bin/python3 and pandas, or Rscript) gives back exactly the
    notes as typed, and the same substitution gives back the text variable.
Exits 77 (CTest's SKIP_RETURN_CODE) with a message when the interpreter or pandas is absent.
"""
import argparse
import csv
import os
import shutil
import sqlite3
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from export_docs_test import fail, run_cli, skip, snippets  # noqa: E402

HEADING = "### Text that looks like a formula"
NOTES = ["=1+1", "-5 dB", "@home", 'a,"b"\nc', "+49 30 1234", "\tindented", "'=x", "''-y",
         "'quoted'", "plain note", "N/A"]
VARIABLE = "-3 dioptres, =corrected"
GUARDED = "=+-@\t\r"


def looks_like_formula(text):
    rest = text.lstrip("'")
    return rest != "" and rest[0] in GUARDED


def make_study(monoplane, source, folder):
    with open(os.path.join(source, "protocols", "demo.toml"), encoding="utf-8") as f:
        protocol = f.read()
    protocol += '\n[[variables]]\nname = "remark"\ntype = "text"\n'
    protocol_path = os.path.join(folder, "demo_with_remark.toml")
    with open(protocol_path, "w", encoding="utf-8") as f:
        f.write(protocol)
    db = os.path.join(folder, "study.db")
    run_cli([monoplane, "study", "run", "--protocol", protocol_path, "--participant", "P01",
             "--db", db, "--headset", "none", "--observer", "default", "--window", "off",
             "--seed", "3", "--var", "remark=" + VARIABLE], "study run")
    for note in NOTES:
        # "--": a note may begin with '-', which is no option.
        run_cli([monoplane, "study", "note", "--db", db, "--participant", "P01", "--", note],
                "study note %r" % note)
    con = sqlite3.connect("file:%s?mode=ro" % db, uri=True)
    stored = [row[0] for row in con.execute("SELECT note FROM session_notes ORDER BY id")]
    con.close()
    if stored != NOTES:
        fail("the database holds the notes %r, not %r as typed" % (stored, NOTES))
    for fmt, name in (("notes-csv", "notes.csv"), ("csv", "trials.csv")):
        run_cli([monoplane, "study", "export", "--db", db, "--format", fmt, "--out",
                 os.path.join(folder, name)], "study export --format " + fmt)


def check_raw_cells(folder):
    """The guard is in the file: an apostrophe more exactly where a spreadsheet would evaluate."""
    with open(os.path.join(folder, "notes.csv"), newline="", encoding="utf-8") as f:
        cells = [row["note"] for row in csv.DictReader(f)]
    want = ["'" + n if looks_like_formula(n) else n for n in NOTES]
    if cells != want:
        fail("notes.csv holds %r, expected %r" % (cells, want))
    with open(os.path.join(folder, "trials.csv"), newline="", encoding="utf-8") as f:
        values = {row["var_remark"] for row in csv.DictReader(f)}
    if values != {"'" + VARIABLE}:
        fail("trials.csv's var_remark holds %r, expected only %r" % (values, "'" + VARIABLE))


def run(command, suffix, code, folder):
    path = os.path.join(folder, "snippet" + suffix)
    with open(path, "w", encoding="utf-8") as f:
        f.write(code)
    done = subprocess.run(command + [path], cwd=folder, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    print(done.stdout)
    if done.returncode != 0:
        fail("the snippet failed (%d):\n%s" % (done.returncode, code))
    return done.stdout


def decoded(output, tag):
    """The texts a check printed as 'tag HEX' lines (hex of UTF-8: line breaks survive)."""
    return [bytes.fromhex(line.split(" ", 1)[1] if " " in line else "").decode("utf-8")
            for line in output.split("\n") if line == tag or line.startswith(tag + " ")]


def compare(got, want, what):
    if got != want:
        fail("%s gave back %r, expected %r" % (what, got, want))
    print("%s: %d texts back exactly as typed" % (what, len(want)))


def part_pandas(docs, folder):
    python = "/usr/bin/python3"  # Debian's python3-pandas is for Debian's interpreter
    if not os.access(python, os.X_OK):
        skip("%s is absent (apt-get install python3-pandas)" % python)
    if subprocess.run([python, "-c", "import pandas"], stderr=subprocess.DEVNULL).returncode:
        skip("pandas is not installed for %s (apt-get install python3-pandas)" % python)
    code = snippets(docs, HEADING, "python")[0]
    check = ('for text in notes["note"]:\n'
             '    print("NOTE", text.encode("utf-8").hex())\n'
             'trials = pd.read_csv("trials.csv", dtype={"var_remark": str})\n'
             'back = trials["var_remark"].str.replace(r"^\'(\'*[=+\\-@\\t\\r])", r"\\1", '
             'regex=True)\n'
             'for text in back.unique():\n'
             '    print("VAR", text.encode("utf-8").hex())\n')
    output = run([python], ".py", code + check, folder)
    compare(decoded(output, "NOTE"), NOTES, "pandas, notes")
    compare(decoded(output, "VAR"), [VARIABLE], "pandas, var_remark")


def part_r(docs, folder):
    rscript = shutil.which("Rscript")
    if not rscript:
        skip("Rscript is absent (apt-get install r-base-core)")
    code = snippets(docs, HEADING, "r")[0]
    check = ('hex <- function(x) paste(sprintf("%02x", as.integer(charToRaw(enc2utf8(x)))), '
             'collapse = "")\n'
             'for (text in notes$note) cat("NOTE", hex(text), "\\n")\n'
             'trials <- read.csv("trials.csv", colClasses = c(var_remark = "character"))\n'
             'for (text in unique(sub("^\'(\'*[=+@\\t\\r-])", "\\\\1", trials$var_remark))) '
             'cat("VAR", hex(text), "\\n")\n')
    output = run([rscript, "--vanilla"], ".R", code + check, folder)
    output = "\n".join(line.rstrip() for line in output.split("\n"))
    compare(decoded(output, "NOTE"), NOTES, "R, notes")
    compare(decoded(output, "VAR"), [VARIABLE], "R, var_remark")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--monoplane", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--part", required=True, choices=["pandas", "r"])
    args = parser.parse_args()
    docs = os.path.join(args.source, "docs", "data.md")
    folder = tempfile.mkdtemp(prefix="csv_injection_")
    try:
        make_study(os.path.abspath(args.monoplane), args.source, folder)
        check_raw_cells(folder)
        {"pandas": part_pandas, "r": part_r}[args.part](docs, folder)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    print("PASS: formula-like CSV text comes back as typed (%s)" % args.part)


if __name__ == "__main__":
    main()
