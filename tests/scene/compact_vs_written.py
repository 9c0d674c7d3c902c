#!/usr/bin/env python3
"""Issue 48 item 1: a scene that says what is repeated (bench/contact_scene.py N --compact: count,
list parameters, E by its diagonal and off-diagonal entries, `blocks = K` for K objects) gives the SAME output as the scene
written out (bench/contact_scene.py N) under `multidof analyze --json` and `stability --scene
--json`: same exit code, same JSON but for the run times ("seconds") and the names the two forms
give the copies (d[k], H[k] against dk, Hk); at N = 4 `stability --scene --certificate` gives the same
claim and evidence on both forms, and both checkers verify the compact one. Also: the compact 128- and
1024-device scenes (one object, and 16 objects of 64) are under 10 KB.

Usage: compact_vs_written.py HAPSTAB [N ...]   (default N = 4 8; exit 1 on any difference)
"""
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
GEN = os.path.join(HERE, '..', '..', 'bench', 'contact_scene.py')


def generate(n, *extra):
    return subprocess.run([sys.executable, GEN, str(n), *extra], capture_output=True, text=True, check=True).stdout


def drop_seconds(v):
    if isinstance(v, dict):
        return {k: drop_seconds(x) for k, x in v.items() if k != 'seconds'}
    if isinstance(v, list):
        return [drop_seconds(x) for x in v]
    return v


def run(hapstab, args):
    p = subprocess.run([hapstab, *args, '--json'], capture_output=True, text=True, check=False)
    if p.returncode not in (0, 1):
        sys.exit(f'{" ".join(args)}: exit {p.returncode}: {p.stderr}')
    text = re.sub(r'\b([dH])\[(\d+)\]', r'\1\2', p.stdout)  # the compact form's names d[k] -> dk
    return p.returncode, drop_seconds(json.loads(text))


def main():
    hapstab, ns = sys.argv[1], [int(a) for a in sys.argv[2:]] or [4, 8]
    failures = 0
    for n, extra in ((128, []), (1024, []), (1024, ['--objects', '16'])):
        size = len(generate(n, '--compact', *extra).encode())
        print(f'compact {n}-device scene {" ".join(extra)}: {size} bytes')
        if size >= 10 * 1024:
            print(f'FAIL: the compact {n}-device scene {" ".join(extra)} is not under 10 KB')
            failures += 1
    with tempfile.TemporaryDirectory() as d:
        for n in ns:
            for extra in ([], ['--delay', '1']) + ((['--objects', '2'],) if n % 8 == 0 else ()):
                files = {}
                for form, flags in (('written', []), ('compact', ['--compact'])):
                    files[form] = os.path.join(d, f'{form}{n}.toml')
                    with open(files[form], 'w') as f:
                        f.write(generate(n, *extra, *flags))
                for cmd in (['multidof', 'analyze', '--scene'], ['stability', '--scene']):
                    w, c = run(hapstab, cmd + [files['written']]), run(hapstab, cmd + [files['compact']])
                    what = f'N = {n} {" ".join(extra)}: {" ".join(cmd[:-1])}'
                    if w != c:
                        failures += 1
                        print(f'FAIL {what}: written-out exit {w[0]}, compact exit {c[0]}; outputs differ')
                    else:
                        stable = c[1].get('stable', c[1].get('stability_concluded'))
                        print(f'same {what}: exit {c[0]}, {"stable" if "stable" in c[1] else "stability_concluded"} = {stable}')
                if n == 4:  # the certificate too: both checkers write the compact form out (check/scene_model.hpp)
                    failures += not same_certificate(hapstab, files, d, f'N = {n} {" ".join(extra)}')
    sys.exit(1 if failures else 0)


def same_certificate(hapstab, files, d, what):
    """stability --scene --certificate on both forms: the same claim and evidence, verified by both checkers."""
    certs = []
    for form in ('written', 'compact'):
        path = os.path.join(d, form + '.json')
        subprocess.run([hapstab, 'stability', '--scene', files[form], '--quiet', '--certificate', path], capture_output=True, check=False)
        if not os.path.exists(path):
            print(f'FAIL {what}: no certificate for the {form} form')
            return False
        with open(path) as f:
            certs.append(json.load(f))
        os.remove(path)
        with open(path, 'w') as f:
            json.dump(certs[-1], f)
    checks = [subprocess.run(cmd + [path], capture_output=True, check=False).returncode
              for cmd in ([hapstab, 'check'], ['/usr/bin/python3', os.path.join(HERE, '..', '..', 'checks', 'hapstab_check.py')])]
    same = certs[0]['claim'] == certs[1]['claim'] and certs[0]['evidence'] == certs[1]['evidence']
    print(f'{"same" if same and checks == [0, 0] else "FAIL"} {what}: stability --certificate, the same claim and evidence '
          f'{same}, the compact one verified by hapstab check and the independent checker {checks}')
    return same and checks == [0, 0]


if __name__ == '__main__':
    main()
