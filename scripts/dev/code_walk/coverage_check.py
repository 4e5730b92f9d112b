#!/usr/bin/env python3
"""Checks walk.py's exclusions against a real run (about 8 minutes on 2 cores).

    python3 scripts/dev/code_walk/coverage_check.py REPO [--work DIR] [--reuse]

Needs REPO/build configured and built (`cmake --build build --target
rockfdem`): the workflows translation units are recompiled with --coverage
into DIR (default /tmp/hops-cov), linked against REPO/build's other
libraries, and `rockfdem run scenes/tunnel-seed.toml` runs under xvfb-run
into a fresh output folder. Then:
  - every function walk.py reads must have run (else: an exclusion is missing);
  - every call walk.py follows must sit on a line that ran (else: the
    function is read from a branch not taken; exclude that call site);
  - functions that ran but walk.py does not read are listed (lambdas, which
    walk.py reads in place, and `= default` members are left out).
--reuse skips the build and the run and compares the coverage already in DIR.
"""
import argparse
import glob
import gzip
import json
import os
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def sh(cmd, **kw):
    print("+", cmd if isinstance(cmd, str) else shlex.join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True, **kw)


def build(repo, work):
    bdir = os.path.join(repo, "build")
    obj = os.path.join(work, "obj")
    os.makedirs(obj, exist_ok=True)
    jobs, seen = [], set()
    for e in json.load(open(os.path.join(bdir, "compile_commands.json"))):
        f = os.path.realpath(e["file"])
        rel = os.path.relpath(f, repo)
        if not (rel.startswith("workflows/") or rel == "build/workflows/default_scene.cpp") \
                or f in seen:
            continue
        seen.add(f)
        args = e.get("arguments") or shlex.split(e["command"])
        if args[0].endswith("ccache"):
            args = args[1:]
        lib = "study" if "/study/" in rel else "main" if rel.endswith("src/main.cpp") else "wf"
        out = os.path.join(obj, lib + "__" + rel.replace("/", "__") + ".o")
        args[args.index("-o") + 1] = out
        args = [a for a in args if a not in ("-O3", "-O2", "-DNDEBUG")] + ["-O0", "--coverage"]
        jobs.append(f"cd {shlex.quote(e['directory'])} && {shlex.join(args)}")
    script = os.path.join(work, "compile.sh")
    open(script, "w").write("\n".join(jobs) + "\n")
    sh(f"tr '\\n' '\\0' < {script} | nice -n 19 xargs -0 -P 2 -I{{}} bash -c '{{}}'", shell=True)
    for lib in ("study", "wf"):
        a = os.path.join(work, f"lib{lib}.a")
        if os.path.exists(a):
            os.remove(a)
        sh(["ar", "qc", a] + sorted(glob.glob(os.path.join(obj, lib + "__*.o"))))
    link = subprocess.run(["ninja", "-C", bdir, "-t", "commands", "bin/rockfdem"],
                          capture_output=True, text=True, check=True).stdout.strip().splitlines()[-1]
    link = link.removeprefix(": && ").split(" && :")[0]
    main_o = glob.glob(os.path.join(obj, "main__*.o"))[0]
    link = link.replace("workflows/CMakeFiles/rockfdem.dir/src/main.cpp.o", main_o)
    link = link.replace("workflows/librockfdem_study.a", os.path.join(work, "libstudy.a"))
    link = link.replace("workflows/librockfdem_workflows.a", os.path.join(work, "libwf.a"))
    link = link.replace("-o bin/rockfdem", f"-o {work}/rockfdem --coverage")
    sh("nice " + link, shell=True, cwd=bdir)


def run(repo, work):
    for g in glob.glob(os.path.join(work, "obj", "*.gcda")):
        os.remove(g)
    out = os.path.join(work, "out")
    sh(["rm", "-rf", out])
    env = dict(os.environ, OMP_NUM_THREADS="2")
    sh(["nice", "-n", "5", "xvfb-run", "-a", os.path.join(work, "rockfdem"), "run",
        "scenes/tunnel-seed.toml", "-o", out], cwd=repo, env=env, stdout=subprocess.DEVNULL)


def coverage(repo, work):
    gdir = os.path.join(work, "gcov")
    sh(["rm", "-rf", gdir])
    os.makedirs(gdir)
    for o in glob.glob(os.path.join(work, "obj", "*.o")):
        subprocess.run(["gcov", "--json-format", "-o", os.path.join(work, "obj"), o], cwd=gdir,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    funcs, lines = {}, {}
    for f in glob.glob(os.path.join(gdir, "*.gcov.json.gz")):
        d = json.load(gzip.open(f))
        for fi in d["files"]:
            path = os.path.realpath(os.path.join(d.get("current_working_directory", ""),
                                                 fi["file"]))
            rel = os.path.relpath(path, repo)
            if rel == "build/workflows/default_scene.cpp":
                rel = "workflows/src/scene/default_scene.cpp.in"  # its lines differ
            if not rel.startswith("workflows/"):
                continue
            for fn in fi.get("functions", []):
                k = (rel, fn["start_line"])
                name, n = funcs.get(k, (fn["demangled_name"], 0))
                funcs[k] = (name, n + fn["execution_count"])
            for ln in fi["lines"]:
                k = (rel, ln["line_number"])
                lines[k] = lines.get(k, 0) + ln["count"]
    return funcs, lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("repo")
    ap.add_argument("--work", default="/tmp/hops-cov")
    ap.add_argument("--reuse", action="store_true")
    a = ap.parse_args()
    repo, work = os.path.realpath(a.repo), a.work
    if not a.reuse:
        os.makedirs(work, exist_ok=True)
        build(repo, work)
        run(repo, work)
    funcs, lines = coverage(repo, work)
    walk_json = os.path.join(work, "walk.json")
    sh([sys.executable, os.path.join(HERE, "walk.py"), repo, "--json", walk_json],
       stdout=subprocess.DEVNULL)
    w = json.load(open(walk_json))

    def ran(f, line, span):  # a function of `f` starting within `span` lines of `line`
        hits = [n for (g, m), (_, n) in funcs.items() if g == f and abs(m - line) <= span]
        return max(hits) if hits else None

    problems = 0
    print("read by walk.py but never run (a missing exclusion):")
    for d in w["read"]:
        n = ran(d["file"], d["line"], 1)
        if n == 0 or (n is None and not d["file"].endswith(".in")):
            problems += 1
            print(f"  {d['file']}:{d['line']} {d['name']}" + (" (no coverage)" if n is None else ""))
    print("calls followed on lines that never ran (read from a branch not taken):")
    for f, line, caller, callee in w["followed"]:
        if not f.endswith(".in") and lines.get((f, line)) == 0:
            problems += 1
            print(f"  {f}:{line} {caller} -> {callee}")
    print("run but not read (lambdas and `= default` left out):")
    read = {(d["file"], d["line"]) for d in w["read"]}
    for (f, line), (name, n) in sorted(funcs.items()):
        if n == 0 or "{lambda" in name or any((f, line + k) in read for k in (-1, 0, 1)):
            continue
        if f.endswith(".in") and any(d["file"] == f and d["name"].split("::")[-1] in name
                                     for d in w["read"]):
            continue  # generated from the .in file: its lines differ
        if name.split("(")[0].split("::")[-1].startswith("~") or name.endswith("()") and \
                name.split("::")[-1].split("(")[0] == name.split("::")[-2]:
            continue  # destructors and default constructors: defaulted ones have no code
        print(f"  {f}:{line} {name[:100]}")
    print(f"{problems} problem(s)")


if __name__ == "__main__":
    main()
