#!/usr/bin/env python3
"""The command line of the demo's programs and scripts, as a user meets it.  One check a call:

  help PROGRAM EXPECTED...       PROGRAM --help: exit 0, "Usage:", every EXPECTED text (options
                                 with their defaults), nothing on standard error, nothing written
  garbage PROGRAM OPTION TEXT [ARG...]
                                 PROGRAM OPTION TEXT ARG...: refused (exit 2), the message names
                                 OPTION and TEXT, nothing written (not even the output folder)
  overwrite ALIGN_PATCH          a non-empty output folder is refused without --overwrite (and left
                                 as it was); with it, no file of the earlier run remains; the
                                 folder the user is in is refused even with --overwrite
  failed_run REPLAY_SESSION SESSION
                                 a run that fails half-way (a `save` into a missing sub-folder)
                                 leaves the output folder as it was, and no staging folder
  progress ALIGN_PATCH           progress lines (iteration, flux, elapsed time) on standard output,
                                 and nothing there with --quiet
  summary ALIGN_PATCH VERSION    summary.json parsed back: the inputs, the version, the runs, and
                                 exactly the files of the folder; each NAME_flux.csv has a row per
                                 surface of NAME_iterations.pvd (0 to the iterations reported),
                                 the first and last with the initial and final flux
  field_directory ALIGN_PATCH    a folder without VTK XML files with times given as --field is
                                 called a folder (not an empty file), exit 1, nothing written
  time_series ALIGN_PATCH        a time series (.pvd) of the flow (1, 2t, 0), and the same steps as
                                 a folder of files named by their times: a run at --time
                                 with a --duration past the last step is warned about and ends
                                 there (summary.json), writes path surfaces over time (their .pvd
                                 lists the data's times after --time, then the end) and path lines
                                 instead of stream surfaces and lines; refused with the file or
                                 time named, nothing written: a series of one step, a --time
                                 outside the steps, --time or --duration without a series, a
                                 folder of two series, a step that cannot be read
  scripts SCRIPTS_DIR            every user script with --help: exit 0, its usage, nothing run
                                 (cmake, apt-get, dpkg-query are fakes that log), nothing written;
                                 run-main-job.sh never takes an option for the output folder
Each check works in a fresh temporary folder and exits non-zero with the reason when it fails.
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def run(args, cwd, env=None):
    p = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def listing(folder):
    """Every entry under `folder`, relative, with its modification time and size for files."""
    entries = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = os.path.join(root, name)
            st = os.stat(path)
            entries[os.path.relpath(path, folder)] = (st.st_mtime_ns, st.st_size) if name in files else None
    return entries


def check_help(program, expected):
    with tempfile.TemporaryDirectory() as work:
        status, out, err = run([program, "--help"], work)
        if status != 0:
            fail(f"{program} --help exited with {status}:\n{err}")
        if not out.startswith("Usage: "):
            fail(f"{program} --help does not start with 'Usage: ':\n{out}")
        for text in expected + ["--help", "--version"]:
            if text not in out:
                fail(f"{program} --help does not mention '{text}':\n{out}")
        if err:
            fail(f"{program} --help wrote to standard error:\n{err}")
        if os.listdir(work):
            fail(f"{program} --help wrote {os.listdir(work)}")


def check_garbage(program, option, text, extra):
    with tempfile.TemporaryDirectory() as work:
        status, out, err = run([program, option, text, "--output", "out"] + extra, work)
        if status != 2:
            fail(f"{program} {option} {text}: exit status {status}, expected 2 (a bad command line)\n{out}{err}")
        if option not in err or f"'{text}'" not in err:
            fail(f"{program} {option} {text}: the message does not name the option and the text:\n{err}")
        if os.listdir(work):
            fail(f"{program} {option} {text} wrote {os.listdir(work)}")


def check_overwrite(align_patch):
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out")
        common = [align_patch, "--faces", "200", "--output", out, "--quiet"]
        status, _, err = run(common + ["--alignment", "orthogonal"], work)
        if status != 0 or not os.path.exists(os.path.join(out, "orthogonal_flux.csv")):
            fail(f"the first run failed ({status}):\n{err}")
        before = listing(out)
        status, _, err = run(common + ["--alignment", "tangential"], work)
        if status == 0:
            fail("a non-empty output folder was accepted without --overwrite")
        if "--overwrite" not in err or "not empty" not in err:
            fail(f"the refusal does not say the folder is not empty and what to do (--overwrite):\n{err}")
        if listing(out) != before:
            fail("the refused run changed the output folder")
        status, _, err = run(common + ["--alignment", "tangential", "--overwrite"], work)
        if status != 0:
            fail(f"--overwrite was refused ({status}):\n{err}")
        files = sorted(os.listdir(out))
        stale = [f for f in files if f.startswith("orthogonal_")]
        if stale:
            fail(f"files of the earlier run remain after --overwrite: {stale}")
        if "tangential_flux.csv" not in files:
            fail(f"the run with --overwrite did not write tangential_flux.csv: {files}")
        if os.listdir(work) != ["out"]:
            fail(f"something was left beside the output folder: {os.listdir(work)}")
        # The folder the user is in is not emptied, even with --overwrite.
        before = listing(out)
        status, _, err = run([align_patch, "--faces", "200", "--output", ".", "--overwrite"], out)
        if status == 0 or "folder you are in" not in err or listing(out) != before:
            fail(f"--output . --overwrite inside an earlier run's folder was not refused ({status}):\n{err}")


def check_failed_run(replay_session, session):
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out")
        os.mkdir(out)
        with open(os.path.join(out, "earlier.csv"), "w") as f:
            f.write("an earlier run's file\n")
        before = listing(out)
        # The session saves once (written), then into a sub-folder that does not exist (fails).
        bad = os.path.join(work, "half.session")
        with open(session) as f:
            text = f.read().rstrip("\n") + "\nsave missing/surface.vtp\n"
        with open(bad, "w") as g:
            g.write(text)
        line = len(text.splitlines())
        status, _, err = run([replay_session, "--output", out, "--overwrite", "--quiet", bad], work)
        if status == 0 or f"line {line}: cannot save missing/surface.vtp" not in err:
            fail(f"a session that cannot save at line {line} did not fail there (status {status}):\n{err}")
        if listing(out) != before:
            fail(f"the failed run changed the output folder: {sorted(listing(out))}")
        if sorted(os.listdir(work)) != ["half.session", "out"]:
            fail(f"the failed run left {sorted(os.listdir(work))}")


def check_progress(align_patch):
    with tempfile.TemporaryDirectory() as work:
        command = [align_patch, "--faces", "200", "--alignment", "orthogonal"]
        status, out, err = run(command + ["--output", "loud"], work)
        # The share comes from the library's callback: iteration 1 of at most 200 is 0.5 %.
        if status != 0 or "orthogonal: iteration 1 (1 % of the most), flux " not in out or " s elapsed" not in out:
            fail(f"no progress line (status {status}):\n{out}{err}")
        status, out, err = run(command + ["--output", "quiet", "--quiet"], work)
        if status != 0 or out:
            fail(f"--quiet printed (status {status}):\n{out}{err}")


def check_summary(align_patch, version):
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out")
        status, _, err = run([align_patch, "--faces", "200", "--size", "1", "--normal", "1,0.4,0.2",
                              "--output", out, "--quiet"], work)
        if status != 0:
            fail(f"align_patch failed ({status}):\n{err}")
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        if summary.get("version") != version:
            fail(f"version {summary.get('version')!r}, expected {version!r}")
        expected_inputs = {"flow": "cylinder", "field": None, "array": None, "center": None,
                           "normal": [1, 0.4, 0.2], "size": 1, "time": None, "duration": None, "faces": 200,
                           "alignment": "both"}
        if summary.get("inputs") != expected_inputs:
            fail(f"inputs {summary.get('inputs')}, expected {expected_inputs}")
        runs = summary.get("runs", [])
        if [r.get("alignment") for r in runs] != ["tangential", "orthogonal"]:
            fail(f"runs {[r.get('alignment') for r in runs]}, expected tangential and orthogonal")
        for r in runs:
            if r.get("normal") != [1, 0.4, 0.2] or r.get("size") != 1:
                fail(f"the {r.get('alignment')} run does not record the placement it used: {r}")
        files = summary.get("files", [])
        missing = [f for f in files if not os.path.isfile(os.path.join(out, f))]
        if missing:
            fail(f"summary.json lists files that do not exist: {missing}")
        # Every file, those of subfolders (the main job's iterations) as relative paths.
        written = sorted(os.path.relpath(os.path.join(d, f), out).replace(os.sep, "/")
                         for d, _, names in os.walk(out) for f in names)
        if sorted(files) != written:
            fail(f"summary.json lists {sorted(files)}, the folder holds {written}")
        for name in ["summary.json", "tangential_aligned.vtp", "orthogonal_flux.csv"]:
            if name not in files:
                fail(f"summary.json does not list {name}")
        # NAME_flux.csv: one row per surface of NAME_iterations.pvd, the initial patch (row 0) and
        # the surface of each iteration the run reports, the last one with the final flux.
        for r in runs:
            name = r["alignment"]
            with open(os.path.join(out, name + "_flux.csv")) as f:
                rows = list(csv.DictReader(f))
            iterations = r["iterations"]
            if [row["iteration"] for row in rows] != [str(k) for k in range(iterations + 1)]:
                fail(f"{name}_flux.csv numbers its rows {[row['iteration'] for row in rows]}, expected 0 to "
                     f"{iterations} (the initial patch and {iterations} iterations)")
            pvd = ET.parse(os.path.join(out, name + "_iterations.pvd")).getroot().find("Collection")
            if len(pvd.findall("DataSet")) != len(rows):
                fail(f"{name}_flux.csv has {len(rows)} rows, {name}_iterations.pvd {len(pvd)} surfaces")
            for row, key in [(rows[0], "initial_normalized_flux"), (rows[-1], "final_normalized_flux")]:
                if abs(float(row["normalized_flux"]) - r[key]) > 1e-9 * max(1.0, abs(r[key])):
                    fail(f"{name}_flux.csv row {row['iteration']}: flux {row['normalized_flux']}, "
                         f"summary.json's {key} {r[key]}")
            if rows[-1]["converged"] != ("1" if r["converged"] else "0"):
                fail(f"{name}_flux.csv's last row says converged={rows[-1]['converged']}, summary.json {r['converged']}")


def check_field_directory(align_patch):
    """A folder without a series given as --field (an OpenFOAM case, say) is called a folder, the
    message says what to give instead, the run fails (exit 1) and writes nothing."""
    with tempfile.TemporaryDirectory() as work:
        case = os.path.join(work, "case")
        os.mkdir(case)
        status, out, err = run([align_patch, "--field", case, "--output", "out", "--quiet"], work)
        if status != 1:
            fail(f"--field FOLDER: exit status {status}, expected 1\n{out}{err}")
        if f"--field: {case} is a folder without VTK XML files whose names end in their time" not in err \
                or "a velocity file (legacy VTK .vtk" not in err or "empty" in err:
            fail(f"--field FOLDER is not called a folder without a time series:\n{err}")
        if sorted(os.listdir(work)) != ["case"]:
            fail(f"--field FOLDER wrote {sorted(os.listdir(work))}")


def write_series(folder, times, names="step_{k}.vti"):
    """A .pvd of ASCII ImageData steps over [0, 1]^3 of the flow (1, 2t, 0) at `times`, the steps
    named by `names` (with the step's index k and time t)."""
    entries = ""
    for k, t in enumerate(times):
        values = " ".join(f"1 {2 * t} 0" for _ in range(5 ** 3))
        with open(os.path.join(folder, names.format(k=k, t=t)), "w") as f:
            f.write('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="0.1">\n'
                    '<ImageData WholeExtent="0 4 0 4 0 4" Origin="0 0 0" Spacing="0.25 0.25 0.25">\n'
                    '<Piece Extent="0 4 0 4 0 4"><PointData><DataArray type="Float32" Name="velocity" '
                    f'NumberOfComponents="3" format="ascii">{values}</DataArray></PointData></Piece>\n'
                    '</ImageData>\n</VTKFile>\n')
        entries += f'<DataSet timestep="{t}" group="" part="0" file="{names.format(k=k, t=t)}"/>\n'
    path = os.path.join(folder, "series.pvd")
    with open(path, "w") as f:
        f.write(f'<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n{entries}'
                '</Collection>\n</VTKFile>\n')
    return path


def check_refused(align_patch, work, refused):
    """Each (ARGS, STATUS, TEXTS) of `refused`: align_patch --field ARGS exits with STATUS, its
    message holds every one of TEXTS, and nothing is written."""
    for args, expected, texts in refused:
        before = sorted(os.listdir(work))
        status, out, err = run([align_patch, "--faces", "200", "--output", "out", "--quiet", "--field"] + args, work)
        if status != expected or any(t not in err for t in texts):
            fail(f"--field {' '.join(args)}: exit {status} (expected {expected}), the message lacks {texts}:\n{err}")
        if sorted(os.listdir(work)) != before:
            fail(f"--field {' '.join(args)} wrote {sorted(set(os.listdir(work)) - set(before))}")


def check_time_series(align_patch):
    with tempfile.TemporaryDirectory() as work:
        series = write_series(work, [0, 0.5, 1])
        # The same steps as a folder of files named by their times, and a folder of two series.
        for folder, names in (("one", "step_{k}.vti"), ("named", "u_{t}.vti"), ("mixed", "u_{t}.vti"),
                              ("mixed", "v_{t}.vti")):
            os.makedirs(os.path.join(work, folder), exist_ok=True)
            pvd = write_series(os.path.join(work, folder), [0.5] if folder == "one" else [0, 0.5, 1], names)
            if folder != "one":
                os.remove(pvd)
        single = os.path.join(work, "one", "series.pvd")
        os.makedirs(os.path.join(work, "broken"))
        broken = write_series(os.path.join(work, "broken"), [0, 0.5, 1])
        os.remove(os.path.join(work, "broken", "step_1.vti"))
        check_refused(align_patch, work, [
            ([broken], 1, [broken, "step 1 (timestep 0.5, file", "step_1.vti"]),
            ([single], 1, [single, "has one time step", "at least two"]),
            ([series, "--time", "1.5"], 1, ["--time: 1.5 is outside the time steps of " + series, "from 0 to 1"]),
            ([series, "--time", "1"], 1, ["--time: 1 is outside"]),
            ([os.path.join(work, "one", "step_0.vti"), "--time", "0"], 2, ["--time and --duration are for a time series"]),
            ([series, "--duration", "-1"], 2, ["--duration"]),
            ([os.path.join(work, "mixed")], 1, ["holds files of two series, u_<time>.vti and v_<time>.vti"])])
        status, out, err = run([align_patch, "--field", os.path.join(work, "named"), "--time", "0.25", "--faces", "200",
                                "--alignment", "tangential", "--output", "out_named"], work)
        if status != 0 or "time series of 3 steps from t = 0 to 1" not in out:
            fail(f"the run on a folder of files with times failed ({status}):\n{out}{err}")
        shutil.rmtree(os.path.join(work, "out_named"))
        status, out, err = run([align_patch, "--field", series, "--time", "0.25", "--duration", "5", "--faces", "200",
                                "--output", "out"], work)
        if status != 0:
            fail(f"the run on a time series failed ({status}):\n{out}{err}")
        if "warning: --duration: 5 from t = 0.25 reaches past the last time step of " + series not in err:
            fail(f"a --duration past the last step is not warned about:\n{err}")
        with open(os.path.join(work, "out", "summary.json")) as f:
            summary = json.load(f)
        expected = {"steps": 3, "start_time": 0, "end_time": 1, "time": 0.25, "duration": 0.75}
        if summary.get("time_series") != expected or summary["inputs"]["time"] != 0.25:
            fail(f"summary.json: time_series {summary.get('time_series')}, inputs {summary['inputs']}; expected {expected}")
        files = summary["files"]
        for name in ("tangential_path_surfaces.vtp", "tangential_path_surfaces.pvd", "orthogonal_path_surfaces.vtp",
                     "orthogonal_path_lines.vtp"):
            if name not in files:
                fail(f"the run on a time series did not write {name}: {files}")
        if any("stream_surfaces" in f or "stream_lines" in f for f in files):
            fail(f"the run on a time series wrote stream surfaces or lines: {files}")
        entries = ET.parse(os.path.join(work, "out", "tangential_path_surfaces.pvd")).getroot()
        times = [float(e.get("timestep")) for e in entries.find("Collection").findall("DataSet")]
        if times != [0.5, 1.0]:
            fail(f"tangential_path_surfaces.pvd lists the times {times}, expected [0.5, 1.0]")


def fake_tools(work):
    """A bin folder of fakes that log their calls: cmake, apt-get, sudo, and dpkg-query (which
    reports every package installed), for scripts that must not build or install."""
    bin_dir = os.path.join(work, "bin")
    os.mkdir(bin_dir)
    log = os.path.join(work, "calls.log")
    for tool in ["cmake", "apt-get", "sudo", "ctest", "g++"]:
        with open(os.path.join(bin_dir, tool), "w") as f:
            f.write(f'#!/bin/sh\necho "{tool} $*" >> "{log}"\n')
    with open(os.path.join(bin_dir, "dpkg-query"), "w") as f:
        f.write(f'#!/bin/sh\necho "dpkg-query $*" >> "{log}"\n'
                'for p in "$@"; do case $p in -*) ;; *) echo "$p install ok installed";; esac; done\n')
    for name in os.listdir(bin_dir):
        os.chmod(os.path.join(bin_dir, name), 0o755)
    env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ["PATH"])
    return env, log


def check_scripts(scripts_dir):
    scripts_dir = os.path.abspath(scripts_dir)
    scripts = sorted(f for f in os.listdir(scripts_dir) if f.endswith(".sh"))
    for script in scripts:
        with tempfile.TemporaryDirectory() as work:
            env, log = fake_tools(work)
            cwd = os.path.join(work, "cwd")
            os.mkdir(cwd)
            status, out, err = run(["bash", os.path.join(scripts_dir, script), "--help"], cwd, env)
            if status != 0:
                fail(f"{script} --help exited with {status}:\n{out}{err}")
            if "Usage" not in out and "usage" not in out:
                fail(f"{script} --help prints no usage:\n{out}")
            if os.path.exists(log):
                with open(log) as f:
                    fail(f"{script} --help ran programs:\n{f.read()}")
            if os.listdir(cwd):
                fail(f"{script} --help wrote {os.listdir(cwd)}")
    # run-main-job.sh: the first argument is the output folder only when it is not an option.
    main_job = os.path.join(scripts_dir, "run-main-job.sh")
    for args, expected in [(["--flow", "sphere"], ["--output", "@CWD@/flow_aligned_surfaces_output", "--flow", "sphere"]),
                           (["results", "--faces", "10"], ["--output", "results", "--faces", "10"]),
                           (["--faces", "10", "--output", "mine"], ["--faces", "10", "--output", "mine"])]:
        with tempfile.TemporaryDirectory() as work:
            env, log = fake_tools(work)
            cwd = os.path.join(work, "cwd")
            os.mkdir(cwd)
            build = os.path.join(work, "build")
            program = os.path.join(build, "demo", "Flow_aligned_surfaces", "align_patch")
            os.makedirs(os.path.dirname(program))
            open(os.path.join(build, "CMakeCache.txt"), "w").close()
            with open(program, "w") as f:
                f.write(f'#!/bin/sh\nfor a in "$@"; do echo "$a"; done > "{work}/align_patch.args"\n')
            os.chmod(program, 0o755)
            env["FAS_BUILD_DIR"] = build
            status, out, err = run(["bash", main_job] + args, cwd, env)
            if status != 0:
                fail(f"run-main-job.sh {' '.join(args)} exited with {status}:\n{out}{err}")
            with open(os.path.join(work, "align_patch.args")) as f:
                got = f.read().split("\n")[:-1]
            want = [a.replace("@CWD@", cwd) for a in expected]
            if got != want:
                fail(f"run-main-job.sh {' '.join(args)} ran align_patch {got}, expected {want}")
            if os.listdir(cwd):
                fail(f"run-main-job.sh {' '.join(args)} created {os.listdir(cwd)} (the program is a fake)")


def main():
    check, args = sys.argv[1], sys.argv[2:]
    if check != "help" and check != "garbage":  # programs and files; the texts stay as they are
        args = [os.path.abspath(a) if os.path.exists(a) else a for a in args]
    else:
        args[0] = os.path.abspath(args[0])
    if check == "help":
        check_help(args[0], args[1:])
    elif check == "garbage":
        check_garbage(args[0], args[1], args[2], args[3:])
    elif check == "overwrite":
        check_overwrite(args[0])
    elif check == "failed_run":
        check_failed_run(args[0], args[1])
    elif check == "progress":
        check_progress(args[0])
    elif check == "field_directory":
        check_field_directory(args[0])
    elif check == "time_series":
        check_time_series(args[0])
    elif check == "summary":
        check_summary(args[0], args[1])
    elif check == "scripts":
        check_scripts(args[0])
    else:
        fail("unknown check " + check)
    print("passed: " + " ".join(sys.argv[1:2] + [os.path.basename(a) for a in sys.argv[2:3]]))


if __name__ == "__main__":
    main()
