#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The design figures of issue 42, measured on a tree or a revision, so that a refactor says
before and after with the same ruler:

    /usr/bin/python3 scripts/design-figures.py            # the working tree
    /usr/bin/python3 scripts/design-figures.py f316abf    # a revision (git archive into a temporary folder)

Figures (sources under core/, app/, widgets/; tests, bench and fuzz targets are callers only):
  - error styles: `QString*` error out-parameters (occurrences and functions), `if (error)`
    guards, `auto fail = [` lambdas, `toOptional()` round trips, functions returning `Result<`;
  - parallel APIs: pure virtuals of MessageSource, the per-graph stats and sample types that exist,
    widget files that include core/ros or core/ros2 headers, Qt item models in transport layers;
  - classes with more than 30 member functions (declared in headers);
  - widget getters (no-argument functions of widgets/ and app/ headers returning a pointer) that
    no source outside tests calls.
Text search, not a compiler: the figures are comparable between revisions, not exact counts of
the language's entities.
"""
import os
import re
import subprocess
import sys
import tarfile
import tempfile

SOURCES = ("core", "app", "widgets")
CALLERS = ("core", "app", "widgets")
TESTS = ("tests", "bench")


def files(root, dirs, exts=(".h", ".cpp")):
    for d in dirs:
        for base, _, names in os.walk(os.path.join(root, d)):
            for n in names:
                if n.endswith(exts):
                    yield os.path.join(base, n)


def read(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def error_styles(root):
    out_param = re.compile(r"QString\s*\*\s*(error|err|errorText|why)\b")
    occurrences = 0
    functions = set()
    guards = fails = optionals = results = 0
    for p in files(root, SOURCES):
        text = strip_comments(read(p))
        for m in out_param.finditer(text):
            occurrences += 1
            head = text[max(0, m.start() - 300):m.start()]
            name = re.findall(r"([A-Za-z_][A-Za-z_0-9:~]*)\s*\(", head)
            if name:
                functions.add(name[-1].split("::")[-1])
        guards += len(re.findall(r"if \((error|err)\)", text))
        fails += len(re.findall(r"auto fail = \[", text))
        optionals += len(re.findall(r"\.toOptional\(\)", text))
        if p.endswith(".h"):
            results += len(re.findall(r"^\s*(?:\[\[nodiscard\]\]\s*)?(?:static\s+)?Result<[^;{]*\(",
                                      text, flags=re.M))
    return occurrences, len(functions), guards, fails, optionals, results


def class_bodies(text):
    """(name, body) of each class or struct defined in text, nested ones included."""
    for m in re.finditer(r"\b(class|struct)\s+(?:[A-Z_]+\s+)?([A-Za-z_]\w*)\s*(?:final\s*)?(?::[^;{]*)?\{", text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        yield m.group(2), text[m.end():i - 1]


def methods_of(body):
    """Member functions declared or defined at the body's own depth."""
    flat, depth = [], 0
    for ch in body:
        if ch == "{":
            depth += 1
            if depth == 1:
                flat.append(";")
        elif ch == "}":
            depth -= 1
        elif depth == 0:
            flat.append(ch)
    count = 0
    for decl in "".join(flat).split(";"):
        decl = re.sub(r"\b(public|private|protected|signals|Q_SIGNALS|slots|Q_SLOTS)\b[^:]*:", "", decl).strip()
        if not decl or decl.startswith(("using", "friend", "typedef", "Q_", "enum")):
            continue
        if re.search(r"[A-Za-z_~]\w*\s*\([^()]*(\([^()]*\)[^()]*)*\)\s*(const)?\s*(noexcept)?\s*(override|final)?\s*(=\s*(0|default|delete))?\s*$", decl) \
                and "=" not in decl.split("(")[0]:
            count += 1
    return count


def big_classes(root, limit=30):
    found = []
    for p in files(root, SOURCES, (".h",)):
        for name, body in class_bodies(strip_comments(read(p))):
            n = methods_of(body)
            if n > limit:
                found.append((n, name, os.path.relpath(p, root)))
    return sorted(found, reverse=True)


def test_only_getters(root):
    getter = re.compile(r"^\s*(?:const\s+)?[A-Za-z_][\w:<>]*\s*\*\s*([a-z]\w*)\(\)\s*(?:const\s*)?(?:;|\{)", re.M)
    callers = {}
    for p in files(root, CALLERS):
        callers[p] = strip_comments(read(p))
    tests = "\n".join(strip_comments(read(p)) for p in files(root, TESTS))
    total, only_tests = 0, []
    for p in files(root, ("widgets", "app"), (".h",)):
        for m in getter.finditer(strip_comments(read(p))):
            name = m.group(1)
            total += 1
            call = re.compile(r"(?:\.|->)" + name + r"\(\)")
            if any(call.search(t) for t in callers.values()):
                continue
            if call.search(tests):
                only_tests.append(f"{os.path.relpath(p, root)}: {name}()")
    return total, only_tests


def parallel_apis(root):
    def exists(pattern):
        return any(re.search(pattern, read(p)) for p in files(root, ("core",), (".h",)))
    source_h = os.path.join(root, "core/latency/messagesource.h")
    # MessageSource's own, not those of the Tap it hands out (the class body up to its "};").
    body = re.search(r"class MessageSource\b.*?\n};", read(source_h), re.S) if os.path.exists(source_h) else None
    pure = len(re.findall(r"=\s*0\s*;", body.group(0))) if body else 0
    # The monitor figures: TopicFigures and the graph-specific structs made of it (not the
    # child's frame body Ros2Protocol::TopicStats).
    stats = ["TopicFigures"] if exists(r"struct\s+TopicFigures\b") else []
    stats += [t for t in ("RosMonitorStats", "TopicStats", "Ros2MonitorStats")
              if exists(r"struct\s+" + t + r"\s*:\s*TopicFigures\b")]
    samples = [t for t in ("SourceArrival", "SourceHead", "Ros2Sample", "RosMessageSample", "Ros2Arrival")
               if exists(r"struct\s+" + t + r"\b")]
    # What the MessageSource implementations offer beside the interface (issue 42's parallel APIs).
    sources_h = [os.path.join(root, f) for f in ("core/ros/rosmonitor.h", "core/ros2/ros2participant.h",
                                                 "core/mqtt/mqttsource.h")]
    parallel = [n for n in ("watchMessages", "takeMessages")
                if any(os.path.exists(p) and re.search(r"\b" + n + r"\(", read(p)) for p in sources_h)]
    includes = set()
    for p in files(root, ("widgets",)):
        if re.search(r'#include\s+"(ros|ros2)/', read(p)):
            includes.add(os.path.relpath(p, root))
    models = []
    for p in files(root, ("core/mqtt", "core/ros", "core/ros2", "core/dds", "core/watch", "core/latency"), (".h",)):
        for m in re.finditer(r"class\s+(\w+)\s*(?:final\s*)?:\s*public\s+QAbstract\w*Model", read(p)):
            models.append(m.group(1))
    return pure, stats, samples, parallel, sorted(includes), sorted(models)


def main():
    rev = sys.argv[1] if len(sys.argv) > 1 else None
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    tmp = None
    if rev:
        tmp = tempfile.TemporaryDirectory()
        archive = subprocess.run(["git", "-C", root, "archive", rev, *SOURCES, *TESTS],
                                 check=True, capture_output=True).stdout
        with tempfile.TemporaryFile() as f:
            f.write(archive)
            f.seek(0)
            tarfile.open(fileobj=f).extractall(tmp.name)
        root = tmp.name
    occ, funcs, guards, fails, optionals, results = error_styles(root)
    print(f"design figures of {rev or 'the working tree'}")
    print(f"  QString* error out-parameters: {occ} occurrences in {funcs} functions")
    print(f"  if (error) guards: {guards}; auto fail = [ lambdas: {fails}; toOptional(): {optionals}; "
          f"functions returning Result<>: {results}")
    pure, stats, samples, parallel, includes, models = parallel_apis(root)
    print(f"  MessageSource pure virtuals: {pure}; stats types: {len(stats)} ({', '.join(stats)}); "
          f"sample types: {len(samples)} ({', '.join(samples)}); parallel APIs: {', '.join(parallel) or 'none'}")
    print(f"  widget files including core/ros or core/ros2: {len(includes)}")
    for i in includes:
        print(f"    {i}")
    print(f"  Qt item models in transport layers: {len(models)} ({', '.join(models)})")
    big = big_classes(root)
    print(f"  classes with more than 30 member functions: {len(big)}")
    for n, name, path in big:
        print(f"    {n:3d} {name} ({path})")
    total, only = test_only_getters(root)
    print(f"  widget getters (pointer, no argument) in widgets/ and app/ headers: {total}, "
          f"called only by tests: {len(only)}")
    if os.environ.get("DESIGN_FIGURES_LIST"):
        for o in only:
            print(f"    {o}")


if __name__ == "__main__":
    main()
