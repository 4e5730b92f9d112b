#!/usr/bin/env python3
"""Hops of a reader following one tunnel run through workflows/ (rules.md).

    python3 scripts/dev/code_walk/walk.py REPO [--report FILE] [--trace FILE]

Parses every translation unit of REPO/workflows/src (and default_scene.cpp.in)
with libclang (flags from REPO/build/compile_commands.json, else the repo's
include folders), collects the function definitions of workflows/ files with
their calls in the order a run makes them, then walks from main() depth
first, each function read once, following only calls whose callee is defined
in workflows/ and skipping what walk_config.toml says a fresh successful
`rockfdem run scenes/tunnel-seed.toml` does not take.

Calls and their order: statements in source order; within an expression the
arguments (and the object) before the call; a lambda passed to a call after
that call, any other lambda where it is written. Constructors (also through
std::make_unique, and members made by a user-written default constructor),
destructors (read right after their constructor) and operators count.
Automatically off the path: calls in catch handlers and throw expressions,
[[noreturn]] calls, and calls in the arguments of a call not made.
Virtual calls through a base named in the config go to the listed classes
(Stage: the classes of the scene's [[stages]] kinds, in order); a member call
on a template-dependent object is mapped the same way by its name.

Hops: a call into another file, and a return to the caller's file when the
caller then makes another followed call (a reader with nothing left to read in
a caller keeps going up). visits(F): calls from another file into a function
of F not yet read. The report also gives the total without returns to a
caller whose next call stays in its own file (a literal reading of rules.md).

Per-unit extraction is cached under cache/ (keyed by the contents of the unit,
of every repo file it includes, and of this script): a rerun after editing a
few files reparses only the units that include them.
"""
import argparse
import re
import glob
import hashlib
import json
import os
import subprocess
import sys
import time
import tomllib
from collections import defaultdict
from concurrent.futures import ProcessPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
CACHE_DIR = os.path.join(os.environ.get("XDG_CACHE_HOME", os.path.expanduser("~/.cache")),
                         "rockfdem-code-walk")
LIBCLANG = "/usr/lib/llvm-14/lib/libclang-14.so.1"
WF = "workflows/"

try:
    import clang.cindex as ci
except ImportError:
    sys.path.append("/usr/lib/python3/dist-packages")
    import clang.cindex as ci

FUNC_KINDS = {"FUNCTION_DECL", "CXX_METHOD", "CONSTRUCTOR", "DESTRUCTOR",
              "CONVERSION_FUNCTION", "FUNCTION_TEMPLATE"}
SCOPE_KINDS = {"NAMESPACE", "CLASS_DECL", "STRUCT_DECL", "CLASS_TEMPLATE",
               "UNEXPOSED_DECL", "LINKAGE_SPEC"}
SKIP_SUBTREES = {"CXX_CATCH_STMT", "CXX_THROW_EXPR"}


# ---------------------------------------------------------------- extraction

def kind(c):
    try:
        return c.kind.name
    except ValueError:  # cursor kinds newer than the Python bindings
        return "?"


def file_of(c):
    f = c.location.file
    return os.path.realpath(f.name) if f else None


def qname(c):
    parts = []
    while c is not None and kind(c) != "TRANSLATION_UNIT":
        if c.spelling:  # anonymous namespaces and lambdas add nothing
            parts.append(c.spelling)
        c = c.semantic_parent
    return "::".join(reversed(parts))


def template_of(r):
    """The primary template of a specialization (a member of a class
    template instance goes to the template's member), else r."""
    seen = 0
    while seen < 4:
        t = ci.conf.lib.clang_getSpecializedCursorTemplate(r)
        if not t or t == r:
            return r
        r, seen = t, seen + 1
    return r


def contains_lambda_only(c):
    """An argument that is a lambda (possibly behind implicit conversions)."""
    for _ in range(4):
        if kind(c) == "LAMBDA_EXPR":
            return True
        ch = list(c.get_children())
        if len(ch) != 1:
            return False
        c = ch[0]
    return False


def is_noreturn(c):
    if c is None:
        return False
    for ch in c.get_children():
        if kind(ch) == "UNEXPOSED_ATTR" and any(t.spelling == "noreturn" for t in ch.get_tokens()):
            return True
    return False


def is_defaulted(c):
    """`= default` or `= delete`: nothing written to read."""
    toks = [t.spelling for t in c.get_tokens()]
    return len(toks) >= 2 and toks[-2] == "=" and toks[-1] in ("default", "delete") or \
        len(toks) >= 3 and toks[-3] == "=" and toks[-2] in ("default", "delete")


def has_body(c):
    if kind(c) in ("CONSTRUCTOR", "DESTRUCTOR") or c.spelling.startswith("operator"):
        if is_defaulted(c):
            return False
    return any(kind(ch) in ("COMPOUND_STMT", "CXX_TRY_STMT") for ch in c.get_children())


SCENE_TYPE = re.compile(r"(^|[^\w:])(rockfdem::workflows::)?Scene($|[^\w])")


def reads_scene(fn):
    """Whether the body names the scene (a parameter, variable or member of
    type Scene): the function reads the scene's settings."""
    stack = list(fn.get_children())
    while stack:
        c = stack.pop()
        if kind(c) in ("DECL_REF_EXPR", "MEMBER_REF_EXPR") and c.referenced is not None:
            try:
                t = c.referenced.type.get_canonical().spelling
            except Exception:
                t = ""
            if SCENE_TYPE.search(t):
                return True
        stack.extend(c.get_children())
    return False


class Extractor:
    def __init__(self, repo):
        self.repo = repo
        self.wf = os.path.join(repo, WF)

    def rel(self, path):
        return os.path.relpath(path, self.repo) if path else None

    def in_wf(self, path):
        return bool(path) and path.startswith(self.wf)

    def callee_pos(self, call, r):
        """Where the reader sees the call: the callee's name token."""
        stack = list(call.get_children())[:1]
        for _ in range(4):
            if not stack:
                break
            c = stack.pop(0)
            if kind(c) in ("MEMBER_REF_EXPR", "DECL_REF_EXPR") and c.spelling == r.spelling:
                return [c.location.line, c.location.column]
            stack = list(c.get_children())[:1]
        return [call.location.line, call.location.column]

    def target(self, call, r):
        """What the call goes to, as plain data, or None (a leaf)."""
        t = template_of(r)
        decl_file = file_of(t)
        if not self.in_wf(decl_file):
            if qname(r) in ("std::make_unique", "std::make_shared") and \
                    r.get_num_template_arguments() > 0:
                decl = r.get_template_argument_type(0).get_declaration()
                if self.in_wf(file_of(decl)):
                    return {"make": decl.get_usr(), "nargs": len(list(call.get_arguments())),
                            "name": qname(decl)}
            return None
        d = r.get_definition()
        tgt = {"usr": t.get_usr(), "name": qname(t)}
        if d is not None and self.in_wf(file_of(d)):
            dt = template_of(d)
            tgt["defloc"] = [self.rel(file_of(dt)), dt.location.line, dt.location.column]
        if kind(r) == "CXX_METHOD" and r.is_virtual_method():
            tgt["virtual"] = True
            tgt["class"] = qname(r.semantic_parent)
            tgt["method"] = r.spelling
            usr = t.get_usr()
            tgt["sig"] = usr[usr.rfind("@F@"):] if "@F@" in usr else None
        if kind(r) == "CONSTRUCTOR":
            for ch in r.semantic_parent.get_children():
                if kind(ch) == "DESTRUCTOR":
                    tgt["dtor"] = ch.get_usr()
        return tgt

    def dependent(self, call):
        """A call in a template or generic lambda whose callee depends on a
        template parameter: a named function of workflows/, or a member
        call known only by its name (resolved by the walk)."""
        ch = list(call.get_children())
        if not ch:
            return None
        c = ch[0]
        while kind(c) == "UNEXPOSED_EXPR" and len(list(c.get_children())) == 1:
            c = list(c.get_children())[0]
        if kind(c) == "DECL_REF_EXPR" and c.referenced is not None:
            return self.target(call, c.referenced)
        if kind(c) == "MEMBER_REF_EXPR" and c.referenced is None:
            toks = [t.spelling for t in c.get_tokens()]
            if toks and (toks[-1][0].isalpha() or toks[-1][0] == "_"):
                return {"dep_member": toks[-1], "name": toks[-1],
                        "pos": [c.location.line, c.location.column]}
        return None

    def calls(self, fn):
        """The calls in the order a run makes them: statements in source
        order; within an expression, arguments and the object before the
        call; a lambda passed to a call after that call (it runs inside it),
        any other lambda where it is written."""
        out = []
        ids = iter(range(1 << 30))

        def visit(c, parent):
            for ch in c.get_children():
                k = kind(ch)
                if k in SKIP_SUBTREES:
                    continue
                if k != "CALL_EXPR":
                    visit(ch, parent)
                    continue
                r = ch.referenced
                if r is not None and any(is_noreturn(x) for x in
                                         (r, r.canonical, template_of(r).canonical)):
                    continue  # a failure: neither it nor its arguments are evaluated
                tgt = self.target(ch, r) if r is not None else self.dependent(ch)
                inner = parent
                if tgt:  # its arguments are evaluated only if it is called
                    tgt["id"], tgt["parent"] = next(ids), parent
                    if "pos" not in tgt:
                        tgt["pos"] = self.callee_pos(ch, r) if r is not None else \
                            [ch.location.line, ch.location.column]
                    inner = tgt["id"]
                lambdas = []
                for a in ch.get_children():
                    if kind(a) in SKIP_SUBTREES:
                        continue
                    if contains_lambda_only(a):
                        lambdas.append(a)
                    else:
                        visit_one(a, inner)
                if tgt:
                    out.append(tgt)
                for a in lambdas:
                    visit_one(a, inner)

        def visit_one(c, parent):
            visit(type("P", (), {"get_children": lambda self: [c]})(), parent)

        if kind(fn) != "CONSTRUCTOR":
            visit(fn, None)
            return out
        # A constructor: members without an initializer whose class has a
        # user-written default constructor are made by it, in member order.
        fields = [f for f in fn.semantic_parent.get_children() if kind(f) == "FIELD_DECL"]
        order = {f.get_usr(): i for i, f in enumerate(fields)}
        explicit = {ch.referenced.get_usr() for ch in fn.get_children()
                    if kind(ch) == "MEMBER_REF" and ch.referenced is not None}
        implicit = [f for f in fields if f.get_usr() not in explicit]
        done = 0

        def implicit_until(limit):
            nonlocal done
            while done < len(implicit) and order[implicit[done].get_usr()] < limit:
                tgt = self.default_ctor(implicit[done])
                if tgt:
                    tgt["id"], tgt["parent"] = next(ids), None
                    tgt["pos"] = [fn.location.line, fn.location.column]  # the constructor
                    out.append(tgt)
                done += 1

        for ch in fn.get_children():
            if kind(ch) == "MEMBER_REF" and ch.referenced is not None:
                implicit_until(order.get(ch.referenced.get_usr(), 0))
            elif kind(ch) in ("COMPOUND_STMT", "CXX_TRY_STMT"):
                implicit_until(len(fields))
            visit_one(ch, None)
        return out

    def default_ctor(self, field):
        decl = field.type.get_declaration()
        if not self.in_wf(file_of(decl)):
            return None
        for c in decl.get_children():
            if kind(c) == "CONSTRUCTOR" and not list(c.get_arguments()) and \
                    not is_defaulted(c):
                return {"usr": c.get_usr(), "name": qname(c), "implicit": True}
        return None

    def extract(self, tu):
        defs, classes = [], []

        def visit(c):
            for ch in c.get_children():
                f = file_of(ch)
                if not self.in_wf(f):
                    continue
                k = kind(ch)
                if k in FUNC_KINDS:
                    if ch.is_definition() and has_body(ch):
                        defs.append({"usr": ch.get_usr(), "name": qname(ch),
                                     "file": self.rel(f), "line": ch.location.line,
                                     "col": ch.location.column, "end": ch.extent.end.line,
                                     "calls": self.calls(ch), "scene": reads_scene(ch)})
                    continue
                if k in SCOPE_KINDS:
                    if k in ("CLASS_DECL", "STRUCT_DECL", "CLASS_TEMPLATE") and ch.is_definition():
                        bases = [qname(b.referenced) for b in ch.get_children()
                                 if kind(b) == "CXX_BASE_SPECIFIER" and b.referenced is not None]
                        classes.append({"usr": ch.get_usr(), "name": qname(ch),
                                        "file": self.rel(f), "bases": bases})
                    visit(ch)

        visit(tu.cursor)
        return defs, classes


# ---------------------------------------------------------------- parsing, cache

def sha(path):
    h = hashlib.sha1()
    with open(path, "rb") as f:
        h.update(f.read())
    return h.hexdigest()


def compile_args(repo, build, tu):
    db = os.path.join(build, "compile_commands.json")
    if os.path.exists(db):
        for e in json.load(open(db)):
            if os.path.realpath(e["file"]) == tu:
                args = e.get("arguments") or e["command"].split()
                keep, skip = [], False
                for a in args[1:]:
                    if skip:
                        skip = False
                        continue
                    if a in ("-o", "-c"):
                        skip = a == "-o"
                        continue
                    if os.path.realpath(a) == tu:
                        continue
                    keep.append(a)
                return keep
    incs = [os.path.join(repo, d, "include") for d in sorted(os.listdir(repo))
            if os.path.isdir(os.path.join(repo, d, "include"))]
    incs += [os.path.join(repo, "coupling/plots/include"), os.path.join(repo, "workflows/src")]
    return ["-std=c++17", "-fopenmp", "-DTOML_HEADER_ONLY=0", "-DTOML_SHARED_LIB=1"] + \
        ["-I" + i for i in incs]


def parse_tu(job):
    repo, tu, args = job
    ci.Config.loaded or ci.Config.set_library_file(LIBCLANG)
    index = ci.Index.create()
    unit = index.parse(tu, args=["-x", "c++"] + args)
    errors = [str(d) for d in unit.diagnostics if d.severity >= 3][:3]
    try:
        defs, classes = Extractor(repo).extract(unit)
    except Exception as e:  # one unit lost is reported, not fatal
        defs, classes = [], []
        errors.insert(0, f"walk.py could not read this unit ({type(e).__name__}: {e})")
    deps = {tu}
    for inc in unit.get_includes():
        p = os.path.realpath(inc.include.name)
        if p.startswith(repo + os.sep) and "/build/" not in p[len(repo):]:
            deps.add(p)
    return {"defs": defs, "classes": classes, "errors": errors,
            "deps": {os.path.relpath(p, repo): sha(p) for p in sorted(deps)}}


def cache_valid(repo, entry):
    for rel, h in entry["deps"].items():
        p = os.path.join(repo, rel)
        if not os.path.exists(p) or sha(p) != h:
            return False
    return True


def load_units(repo, build, jobs, use_cache):
    tus = []
    for root, _, files in os.walk(os.path.join(repo, "workflows/src")):
        tus += [os.path.join(root, f) for f in files if f.endswith((".cpp", ".cpp.in"))]
    tus.sort()
    os.makedirs(CACHE_DIR, exist_ok=True)
    for old in glob.glob(os.path.join(CACHE_DIR, "*.json")):  # entries unused for 30 days
        if time.time() - os.path.getatime(old) > 30 * 86400:
            os.remove(old)
    units, todo = {}, []
    for tu in tus:
        args = compile_args(repo, build, tu)
        rel = os.path.relpath(tu, repo)
        key = hashlib.sha1((rel + "\0" + "\0".join(a.replace(repo, "<R>") for a in args) +
                            "\0" + sha(os.path.abspath(__file__))).encode()).hexdigest()
        path = os.path.join(CACHE_DIR, key + ".json")
        if use_cache and os.path.exists(path):
            entry = json.load(open(path))
            if cache_valid(repo, entry):
                units[rel] = entry
                continue
        todo.append((rel, path, (repo, tu, args)))
    if todo:
        print(f"parsing {len(todo)} of {len(tus)} translation units ...", file=sys.stderr)
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            for (rel, path, _), entry in zip(todo, pool.map(parse_tu, [t[2] for t in todo])):
                units[rel] = entry
                with open(path, "w") as f:
                    json.dump(entry, f)
    return units


# ---------------------------------------------------------------- config

def short(name):
    return name.replace("rockfdem::workflows::", "")


def matches(pattern, name):
    """A configured name matches a qualified name when it is a suffix of it
    at a `::` boundary: `Run::read_restart` matches rockfdem::...::Run::read_restart."""
    return name == pattern or name.endswith("::" + pattern)


class Config:
    def __init__(self, path, repo):
        self.data = tomllib.load(open(path, "rb"))
        ex = self.data.get("exclude", {})
        self.functions = ex.get("functions", [])
        self.calls = []
        for spec in ex.get("calls", []):
            lhs, rhs = [s.strip() for s in spec.split("->")]
            nth = None
            if "#" in rhs:
                rhs, n = rhs.split("#")
                rhs, nth = rhs.strip(), int(n)
            self.calls.append((spec, lhs, rhs, nth))
        self.only = ex.get("only_calls", {})
        self.virtual = self.data.get("virtual", {})
        st = self.data.get("stages", {})
        self.stage_base = st.get("base", "Stage")
        self.stage_classes = st.get("classes", {})
        self.scene_path = self.data.get("scene", "scenes/tunnel-seed.toml")
        self.scene = tomllib.load(open(os.path.join(repo, self.scene_path), "rb"))
        skip = set(st.get("not_explicit", ["insitu"]))
        self.stage_kinds = [s["kind"] for s in self.scene.get("stages", [])
                            if s["kind"] not in skip]
        self.used = set()

    def function_excluded(self, name):
        for p in self.functions:
            if matches(p, name):
                self.used.add(("f", p))
                return True
        return False

    def call_excluded(self, caller, callee, nth):
        for p, keep in self.only.items():
            if matches(p, caller):
                self.used.add(("o", p))
                hit = [k for k in keep if matches(k, callee)]
                for k in hit:
                    self.used.add(("o", p + " -> " + k))
                if not hit:
                    return True
        for spec, lhs, rhs, n in self.calls:
            if matches(lhs, caller) and matches(rhs, callee) and (n is None or n == nth):
                self.used.add(("c", spec))
                return True
        return False


# ---------------------------------------------------------------- model

class Model:
    def __init__(self, units):
        self.defs, self.by_loc, self.classes = {}, {}, {}
        self.errors = {}
        for rel, u in sorted(units.items()):
            if u["errors"]:
                self.errors[rel] = u["errors"]
            for d in u["defs"]:
                self.defs.setdefault(d["usr"], d)
                self.by_loc.setdefault((d["file"], d["line"], d["col"]), d["usr"])
            for c in u["classes"]:
                self.classes.setdefault(c["name"], c)
        self.by_name = defaultdict(list)
        for usr, d in self.defs.items():
            self.by_name[d["name"]].append(usr)

    def resolve_static(self, t):
        if "make" in t:
            return self.ctor_for(t["name"], t["nargs"])
        if t["usr"] in self.defs:
            return t["usr"]
        if "defloc" in t:
            return self.by_loc.get(tuple(t["defloc"]))
        return None

    def ctor_for(self, cls, nargs):
        base = cls.split("::")[-1]
        cands = [u for u in self.by_name.get(cls + "::" + base, [])]
        if not cands:
            return None
        # the constructor whose USR names nargs parameters (count '#'-separated args)
        def arity(u):
            sig = u[u.rfind("@F@"):]
            return sig.count("#") - (1 if sig.endswith("#") else 0)
        exact = [u for u in cands if arity(u) == nargs]
        return (exact or cands)[0]

    def class_chain(self, name):
        """name, then its bases depth first."""
        out, todo = [], [name]
        while todo:
            n = todo.pop(0)
            c = self.find_class(n)
            if c is None or c["name"] in out:
                continue
            out.append(c["name"])
            todo = c["bases"] + todo
        return out

    def find_class(self, pattern):
        if pattern in self.classes:
            return self.classes[pattern]
        hits = [c for n, c in self.classes.items() if matches(pattern, n)]
        return hits[0] if len(hits) == 1 else None

    def method_in(self, cls_name, method, sig):
        """cls_name's own definition of `method` or the nearest base's."""
        for cname in self.class_chain(cls_name):
            cands = self.by_name.get(cname + "::" + method, [])
            same = [u for u in cands if sig and u.endswith(sig)]
            if same or cands:
                return (same or cands)[0]
        return None


# ---------------------------------------------------------------- walk

class Walk:
    def __init__(self, model, cfg):
        self.m, self.cfg = model, cfg
        self.read, self.order = set(), []
        self.hops, self.visits = [], defaultdict(list)
        self.pos = None
        self.warnings = []
        self.unmapped = set()
        self.unresolved = set()  # member calls on dependent types matched by no function
        self.followed = []  # (caller file, call line, caller, callee) of every call followed
        self.stage_impl = self.stage_classes()
        for base, impls in cfg.virtual.items():
            for c in [base] + impls:
                if self.m.find_class(c) is None:
                    self.warnings.append(f"[virtual] {base}: class {c} not found (renamed?)")

    def stage_classes(self):
        out = []
        for k in self.cfg.stage_kinds:
            cls = self.cfg.stage_classes.get(k)
            if cls is None:  # the Stage class in the file of make_<kind>_stage()
                makers = [self.m.defs[u] for n, us in self.m.by_name.items()
                          if n.split("::")[-1] == f"make_{k}_stage" for u in us]
                if makers:
                    f = makers[0]["file"]
                    hits = [c["name"] for c in self.m.classes.values() if c["file"] == f and
                            any(matches(self.cfg.stage_base, b) for b in
                                self.m.class_chain(c["name"])[1:])]
                    cls = hits[0] if hits else None
            if cls is None:
                self.warnings.append(f"stage kind '{k}': no class found (set [stages.classes])")
            else:
                out.append(cls)
        return out

    def targets(self, t):
        if "dep_member" in t:  # `x.name()` on a dependent type: a mapped base's method
            m = t["dep_member"]
            for base in [self.cfg.stage_base] + list(self.cfg.virtual):
                cls = self.m.find_class(base)
                if cls and (self.m.by_name.get(cls["name"] + "::" + m) or any(
                        n.endswith("::" + m) and self.m.find_class(n.rsplit("::", 1)[0]) and
                        cls["name"] in self.m.class_chain(n.rsplit("::", 1)[0])
                        for n in self.m.by_name)):
                    return self.targets({"virtual": True, "class": cls["name"], "method": m,
                                         "sig": None, "name": cls["name"] + "::" + m})
            if any(n.endswith("::" + m) for n in self.m.by_name):
                self.unresolved.add(m)  # a name of workflows/ too: say it was not followed
            return []
        if t.get("virtual"):
            base = t["class"]
            impls = None
            if matches(self.cfg.stage_base, base):
                impls = self.stage_impl
            else:
                for pat, lst in self.cfg.virtual.items():
                    if matches(pat, base):
                        impls = lst
            if impls is not None:
                out = []
                for c in impls:
                    u = self.m.method_in(c, t["method"], t["sig"])
                    if u is None and self.m.find_class(c) is None:
                        self.warnings.append(f"virtual map: class {c} not found")
                    if u and u not in out:
                        out.append(u)
                return out
            if any(matches(base, b) for c in self.m.classes.values() for b in c["bases"]):
                self.unmapped.add(short(t["name"]))  # a base with overrides, not mapped
        u = self.m.resolve_static(t)
        return [u] if u else []

    def dtor_of(self, ctor):
        """A constructor's class's user-written destructor: read right after
        the constructor, as if it called it (the object dies at scope end)."""
        parts = self.m.defs[ctor]["name"].split("::")
        if len(parts) < 2 or parts[-1] != parts[-2]:
            return None
        us = self.m.by_name.get("::".join(parts[:-1] + ["~" + parts[-1]]), [])
        return us[0] if us else None

    def enter(self, usr, depth):
        d = self.m.defs[usr]
        self.read.add(usr)
        self.order.append((depth, usr))
        # Pass 1: the calls not made on this path; the calls in their
        # arguments (evaluated before them) are not made either.
        seen, excluded, dropped, parent = defaultdict(int), set(), set(), {}
        for t in d["calls"]:
            parent[t["id"]] = t.get("parent")
            targets = self.targets(t)
            for u in targets:
                name = self.m.defs[u]["name"]
                seen[name] += 1
                if self.cfg.call_excluded(d["name"], name, seen[name]) or \
                        self.cfg.function_excluded(name):
                    dropped.add((t["id"], u))
            if targets and all((t["id"], u) in dropped for u in targets):
                excluded.add(t["id"])

        def skipped(i):
            while i is not None:
                if i in excluded:
                    return True
                i = parent.get(i)
            return False

        dtor = self.dtor_of(usr)
        tail = [{"id": -1, "pos": [d["end"], 0], "dtor": dtor}] if dtor else []
        for t in d["calls"] + tail:
            if skipped(t["id"]):
                continue
            for u in ([t["dtor"]] if t.get("dtor") and t["id"] == -1 else self.targets(t)):
                callee = self.m.defs[u]
                if u in self.read or (t["id"], u) in dropped:
                    continue
                if self.pos != d["file"]:
                    same = callee["file"] == d["file"]
                    self.hops.append(("return", self.pos, self.last, d, same))
                    self.pos = d["file"]
                if callee["file"] != d["file"]:
                    self.hops.append(("call", d["file"], d, callee, t["pos"][0]))
                    self.visits[callee["file"]].append((d, callee))
                self.followed.append((d["file"], t["pos"][0], d["name"], callee["name"]))
                self.pos = callee["file"]
                self.last = callee
                self.enter(u, depth + 1)  # leaves self.last, self.pos where reading ended

    def run(self, entry):
        self.pos, self.last = self.m.defs[entry]["file"], self.m.defs[entry]
        self.visits[self.pos]  # the entry file, visited without a call
        self.enter(entry, 0)


def fn_label(d):
    return f"{d['file'].replace(WF + 'src/', '').replace(WF, '')}:{short(d['name'])}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("repo")
    ap.add_argument("--config", default=os.path.join(HERE, "walk_config.toml"))
    ap.add_argument("--build", help="build dir with compile_commands.json (default REPO/build)")
    ap.add_argument("--report", help="write the report here (default: stdout only)")
    ap.add_argument("--trace", help="write the reading order (indented) here")
    ap.add_argument("--json", help="write the functions read and the hops as JSON here")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-cache", action="store_true")
    a = ap.parse_args()
    repo = os.path.realpath(a.repo)
    units = load_units(repo, a.build or os.path.join(repo, "build"), a.jobs, not a.no_cache)
    model = Model(units)
    cfg = Config(a.config, repo)
    entry = [u for u in model.by_name.get("main", []) if model.defs[u]["file"].endswith("main.cpp")]
    if not entry:
        sys.exit("no main() in workflows/")
    w = Walk(model, cfg)
    w.run(entry[0])
    print(render(repo, model, cfg, w, full=False))
    if a.report:
        with open(a.report, "w") as f:
            f.write(render(repo, model, cfg, w, full=True) + "\n")
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"read": [model.defs[u] | {"depth": dep, "calls": None}
                                for dep, u in w.order],
                       "followed": w.followed,
                       "visits": {k: len(v) for k, v in w.visits.items()},
                       "hops": len(w.hops)}, f, indent=1)
    if a.trace:
        with open(a.trace, "w") as f:
            for depth, u in w.order:
                d = model.defs[u]
                f.write(f"{'  ' * depth}{short(d['name'])}  [{d['file']}:{d['line']}]\n")


def scene_trail(model, w):
    """Following the scene: the functions that read it (name a Scene), in
    reading order; a visit is an entry into a file from another one."""
    seq, stack = [], []  # stack: the file of the function read at each depth
    for depth, u in w.order:
        d = model.defs[u]
        del stack[depth:]
        caller = stack[-1] if stack else None
        stack.append(d["file"])
        if d.get("scene"):
            seq.append((d["file"], d["name"], caller != d["file"]))
    visits, calls, names, hops, prev = defaultdict(int), defaultdict(int), defaultdict(list), 0, None
    for f, name, by_call in seq:
        if f != prev:
            visits[f] += 1
            hops += prev is not None
        calls[f] += by_call
        names[f].append(short(name) + ("" if by_call else "*"))
        prev = f
    files = sorted(visits, key=lambda f: (-calls[f], -visits[f], f))
    L = [f"following the scene: {len(seq)} functions read it, {hops} hops through "
         f"{len(files)} files; files entered by call more than twice: "
         f"{sum(calls[f] > 2 for f in files)}; entered more than twice counting returns: "
         f"{sum(visits[f] > 2 for f in files)}",
         "  (by call, with returns; * = called from its own file)"]
    for f in files:
        L.append(f"  scene {calls[f]} {visits[f]}  {f.replace(WF + 'src/', '')}: "
                 f"{', '.join(names[f])}")
    L.append("  scene trail: " + " > ".join(
        f"{f.replace(WF + 'src/', '')}:{short(n)}" for f, n, _ in seq))
    return L


def render(repo, model, cfg, w, full):
    """The report: totals, warnings, visits by call per file; with `full`,
    every file's entering calls and the hop list (else only for files
    visited more than twice)."""
    L = []
    try:
        head = subprocess.run(["git", "-C", repo, "log", "-1", "--format=%h %s"],
                              capture_output=True, text=True).stdout.strip()[:90]
    except OSError:
        head = "?"
    calls = [h for h in w.hops if h[0] == "call"]
    rets = [h for h in w.hops if h[0] == "return"]
    same = [h for h in rets if h[4]]
    files = sorted(w.visits, key=lambda f: (-len(w.visits[f]), f))
    over = [f for f in files if len(w.visits[f]) > 2]
    L.append(f"repo {repo} @ {head}")
    L.extend(scene_trail(model, w))
    L.append(f"scene {cfg.scene_path}: stages {', '.join(cfg.stage_kinds)}")
    L.append(f"total hops: {len(calls) + len(rets)} (calls {len(calls)}, returns {len(rets)}); "
             f"{len(calls) + len(rets) - len(same)} if a return to a caller whose next call "
             f"stays in its own file is not counted ({len(same)} such returns)")
    L.append(f"workflows files visited: {len(files)}; functions read: {len(w.read)}; "
             f"files visited by call more than twice: {len(over)}")
    for msg in sorted(set(w.warnings)):
        L.append("WARNING: " + msg)
    only = [("o", p) for p in cfg.only] + [("o", p + " -> " + k) for p, ks in cfg.only.items()
                                           for k in ks]
    for kind_, spec in [("f", p) for p in cfg.functions] + [("c", c[0]) for c in cfg.calls] + only:
        if (kind_, spec) not in cfg.used:
            exists = kind_ != "f" or any(matches(spec, n) for n in model.by_name)
            why = "matched no call on the path" if exists else "names no function (renamed?)"
            L.append(f"WARNING: exclusion '{spec}' {why}")
    if w.unmapped:
        L.append("NOTE: virtual calls through a base with overrides, taken statically "
                 "(add the base to [virtual]): " + ", ".join(sorted(w.unmapped)))
    if w.unresolved:
        L.append("NOTE: member calls on template-dependent objects not followed (no mapped "
                 "base has the name; check by hand): " +
                 ", ".join(sorted(w.unresolved)))
    read_files = {model.defs[u]["file"] for u in w.read}
    for rel, errs in model.errors.items():
        if rel in read_files or errs[0].startswith("walk.py"):
            L.append(f"WARNING: parse errors in {rel} (its calls may be missing): {errs[0]}")
    L.append(f"rerun: python3 {HERE}/walk.py REPO [--report FILE] [--trace FILE]  (about 30 s "
             f"cold, 1 s cached); exclusions against a real run: python3 {HERE}/coverage_check.py "
             f"REPO  (about 8 min)")
    L.append("")
    if not full:  # one line per file; entering calls as callee (caller file:caller)
        L.append("visits by call per file, descending; for files visited more than twice the "
                 "entering calls: callee <- caller file:function")
        small = []
        for f in files:
            name = f.replace(WF + "src/", "").replace(WF, "")
            if len(w.visits[f]) > 2:
                L.append(f"{len(w.visits[f]):2d} {name}: " + "; ".join(
                    f"{short(ce['name'])} <- {fn_label(cr)}" for cr, ce in w.visits[f]))
            else:
                small.append(f"{len(w.visits[f])} {name}")
        L.append("<= 2: " + ", ".join(small))
        return "\n".join(L)
    L.append("visits by call per file, descending (entering calls: caller file:function -> callee)")
    for f in files:
        L.append(f"{len(w.visits[f]):3d}  {f.replace(WF + 'src/', '').replace(WF, '')}")
        for caller, callee in w.visits[f]:
            L.append(f"       {fn_label(caller)} -> {short(callee['name'])}")
    L.append("")
    L.append("hop list, in reading order (call: caller -> callee; return: where the reader was "
             "-> the caller it goes back to)")
    i = 0
    for h in w.hops:
        i += 1
        if h[0] == "call":
            L.append(f"{i:4d} call   {fn_label(h[2])} -> {fn_label(h[3])}  (line {h[4]})")
        else:
            L.append(f"{i:4d} return {fn_label(h[2])} -> {fn_label(h[3])}" +
                     ("  (its next call stays in its file)" if h[4] else ""))
    return "\n".join(L)


if __name__ == "__main__":
    main()
