#!/usr/bin/env python3
"""Check that src/ imports point down the layers, that no two files import
each other and that the modules import each other without a cycle
(docs/architecture.md).

Layers, low to high (a file may import its own layer or a lower one):
  0 cancel, input, output, param, dof, delimited, material, contact   1 scene   2 assembly, error   3 solve
  4 analysis, fe        5 study   6 explore, calibrate
  7 report (renders the results of all below)   8 bin (the CLI)
An import is any `crate::a::b` or `super::...` path in a file (use lines
and paths in code alike), resolved to the file that defines the module.
Module cycles are looked for among the top-level modules (`report` imports
`calibrate` if any file of report/ imports one of calibrate/) and among the
submodules of every module (e.g. `study::summary` and `study::stream`);
a module importing its own parent or child is no cycle.
Run from the repository root: python3 tools/layers.py
"""

import os
import re
import sys

LAYER = {
    "cancel": 0, "input": 0, "output": 0, "param": 0, "dof": 0, "delimited": 0, "lane": 0, "material": 0, "contact": 0, "scene": 1, "assembly": 2, "error": 2,
    "solve": 3, "analysis": 4, "fe": 4, "study": 5, "explore": 6,
    "calibrate": 6, "report": 7, "bin": 8,
}


def module_of(path):
    """src/a/b.rs -> ['a', 'b']; src/a/mod.rs -> ['a']; src/lib.rs -> []."""
    rel = os.path.relpath(path, "src")[:-3].split(os.sep)
    if rel[-1] in ("mod", "lib"):
        rel = rel[:-1]
    return rel


def file_of(mod):
    """The file defining the longest prefix of `mod` (a module path)."""
    for n in range(len(mod), 0, -1):
        base = os.path.join("src", *mod[:n])
        for f in (base + ".rs", os.path.join(base, "mod.rs")):
            if os.path.exists(f):
                return f
    return None


def strip_comments(text):
    return "\n".join(l.split("//", 1)[0] for l in text.splitlines())


def imports(path, text):
    me = module_of(path)  # `self`; each `super` drops one name
    out = set()
    body = strip_comments(text)
    # use-trees: expand `use a::{b, c::d}` one level
    for m in re.finditer(r"\buse\s+([^;]+);", body):
        tree = re.sub(r"\s+", "", m.group(1))
        head, _, rest = tree.partition("{")
        paths = [head + p for p in rest.rstrip("}").split(",")] if rest else [head]
        for p in paths:
            out.add(p.split(" as ")[0])
    for m in re.finditer(r"\b((?:crate|super)(?:::\w+)+)", body):
        out.add(m.group(1))
    files = set()
    for p in out:
        parts = [x for x in p.split("::") if x and x != "self"]
        if not parts or parts[0] not in ("crate", "super"):
            continue
        if parts[0] == "crate":
            mod = parts[1:]
        else:
            base = list(me)
            while parts and parts[0] == "super":
                parts.pop(0)
                base = base[:-1]
            mod = base + parts
        f = file_of(mod)
        if f and f != path:
            files.add(f)
    return files


def layer(path):
    top = module_of(path)
    return LAYER.get(top[0]) if top else None


def module_edges(graph):
    """Edges between sibling modules: {parent: {(a, b): (file, imported)}},
    `a` and `b` children of `parent` (a module path as a tuple)."""
    edges = {}
    for f, deps in graph.items():
        mf = module_of(f)
        for d in deps:
            md = module_of(d)
            n = 0
            while n < min(len(mf), len(md)) and mf[n] == md[n]:
                n += 1
            if n < len(mf) and n < len(md):
                key = (mf[n], md[n])
                edges.setdefault(tuple(mf[:n]), {}).setdefault(key, (f, d))
    return edges


def cycles(edges):
    """One cycle per strongly connected component of more than one node
    (Tarjan), as a list of nodes with the first repeated at the end."""
    succ = {}
    for a, b in edges:
        succ.setdefault(a, []).append(b)
        succ.setdefault(b, [])
    index, low, stack, on, comps = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(succ[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                comps.append(set(comp))

    for v in sorted(succ):
        if v not in index:
            visit(v)
    out = []
    for comp in comps:
        # The shortest way back to the first node (breadth first).
        start = min(comp)
        prev, todo = {start: None}, [start]
        while todo:
            v = todo.pop(0)
            for w in sorted(succ[v]):
                if w in comp and w not in prev:
                    prev[w] = v
                    todo.append(w)
        last = min(v for v in comp if start in succ[v] and v in prev)
        path = [last]
        while prev[path[-1]] is not None:
            path.append(prev[path[-1]])
        out.append(path[::-1] + [start])
    return out


def main():
    files = []
    for root, _, names in os.walk("src"):
        files += [os.path.join(root, n) for n in names if n.endswith(".rs")]
    graph = {}
    bad = []
    for f in sorted(files):
        if f.startswith("src/bin/"):
            continue
        graph[f] = imports(f, open(f).read())
    for f, deps in graph.items():
        lf = layer(f)
        for d in sorted(deps):
            ld = layer(d)
            if lf is not None and ld is not None and ld > lf:
                bad.append(f"up: {f} (layer {lf}) imports {d} (layer {ld})")
            if f in graph.get(d, ()) and f < d:
                bad.append(f"cycle: {f} <-> {d}")
    for parent, edges in sorted(module_edges(graph).items()):
        for c in cycles(edges):
            name = lambda m: "::".join(parent + (m,))
            via = "; ".join(
                f"{edges[(a, b)][0]} imports {edges[(a, b)][1]}" for a, b in zip(c, c[1:])
            )
            bad.append(f"module cycle: {' -> '.join(map(name, c))} ({via})")
    for b in bad:
        print(b)
    print(f"{len(graph)} files, {sum(len(d) for d in graph.values())} imports, {len(bad)} problems")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
