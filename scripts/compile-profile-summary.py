#!/usr/bin/env python3
"""Summary of a scripts/compile-profile build: clang's -ftime-trace files and the launcher's log.

Prints (1) the total and the slowest translation units by wall time; (2) the headers whose parsing
costs most, summed over every unit that includes them (a "Source" event's own duration: time in
that header's text, nested headers included); (3) the templates whose instantiation costs most,
summed over units (InstantiateClass/InstantiateFunction, by name up to the first '<'); (4) the
frontend/backend split. Usage: compile-profile-summary.py BUILD_DIR [TOP]"""
import collections, json, os, re, sys

def main():
    build = sys.argv[1]
    top = int(sys.argv[2]) if len(sys.argv) > 2 else 15
    times = []
    with open(os.path.join(build, "compile-times.tsv")) as f:
        for line in f:
            sec, obj = line.rstrip("\n").split("\t")
            times.append((float(sec), os.path.relpath(obj, build) if obj else "?"))
    total = sum(t for t, _ in times)
    print(f"{len(times)} compiles, {total:.0f} s of compile time in all (CPU-bound: ~wall x cores)")
    print(f"\nslowest {top} units (s, share of all):")
    for t, o in sorted(times, reverse=True)[:top]:
        print(f"  {t:7.1f}  {100 * t / total:4.1f}%  {o}")
    by_dir = collections.Counter()
    for t, o in times:
        key = re.sub(r"CMakeFiles/([^/]+)\.dir/.*", r"\1", o)
        by_dir[key] += t
    print("\nby target (s):")
    for k, t in by_dir.most_common(top):
        print(f"  {t:7.1f}  {k}")
    headers = collections.Counter()
    templates = collections.Counter()
    phases = collections.Counter()
    units = 0
    for root, _, files in os.walk(build):
        for name in files:
            if not name.endswith(".json") or ".cpp" not in name:
                continue
            try:
                events = json.load(open(os.path.join(root, name)))["traceEvents"]
            except (ValueError, KeyError):
                continue
            units += 1
            # A header's inclusive time is counted once per unit: nested Source events of the same
            # header (re-entered guards) would otherwise double it.
            seen = collections.Counter()
            for e in events:
                n, d = e.get("name"), e.get("dur", 0)
                det = e.get("args", {}).get("detail", "")
                if n == "Source":
                    seen[det] = max(seen[det], d)
                elif n in ("InstantiateClass", "InstantiateFunction"):
                    templates[det.split("<")[0]] += d
                elif n.startswith("Total ") and n[6:] in ("Frontend", "Backend", "Source",
                                                          "InstantiateFunction", "InstantiateClass",
                                                          "CodeGen Function", "Optimizer"):
                    phases[n[6:]] += d
            for h, d in seen.items():
                headers[h] += d
    print(f"\n{units} time traces read")
    print("\nphases summed over units (s):")
    for k, d in phases.most_common():
        print(f"  {d / 1e6:8.1f}  {k}")
    def short(h):
        for p in ("/usr/include/", "/toolbox/"):
            if p in h:
                return h.split(p, 1)[1]
        return h
    print(f"\nheaders by parse time summed over units (s, inclusive of what they include), top {top}:")
    for h, d in headers.most_common(top):
        print(f"  {d / 1e6:8.1f}  {short(h)}")
    print(f"\ntemplates by instantiation time summed over units (s, nested counted in each), top {top}:")
    for h, d in templates.most_common(top):
        print(f"  {d / 1e6:8.1f}  {h[:110]}")

main()
