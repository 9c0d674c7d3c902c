#!/usr/bin/env python3
"""Writes the one-DOF wall of tests/cli/scenes/multidof_delay_wall.toml behind D samples of network
delay (issue 39 item 5), optionally with other K and B ([parameters]). The wall as written (K = 20000,
B = 5) makes (16) infeasible from D = 2 on (the frequency-domain witness decides); the soft wall
(--K 50 --B 1) stays feasible, and is the structured Riccati path's delay benchmark.

Usage: bench/delay_wall_scene.py D [--K 50] [--B 1] > scene.toml
       build/hapstab multidof analyze --scene scene.toml
"""
import argparse
import pathlib
import sys

WALL = pathlib.Path(__file__).resolve().parent.parent / 'tests' / 'cli' / 'scenes' / 'multidof_delay_wall.toml'


def scene(delay, K=None, B=None):
    text = WALL.read_text()
    for key, old, new in (('samples', '"1"', delay), ('K', '"20000"', K), ('B', '"5"', B)):
        line = f'{key} = {old}\n'
        if line not in text:
            sys.exit(f'{WALL}: no line {line.strip()!r} to replace')
        if new is not None:
            text = text.replace(line, f'{key} = "{new}"\n', 1)
    return text


if __name__ == '__main__':
    ap = argparse.ArgumentParser(description='the delayed one-DOF wall of issue 39')
    ap.add_argument('D', type=int, help='delay in samples (>= 1)')
    ap.add_argument('--K', help='wall stiffness (exact, e.g. 50)')
    ap.add_argument('--B', help='wall damping (exact, e.g. 1)')
    a = ap.parse_args()
    if a.D < 1:
        sys.exit('usage: bench/delay_wall_scene.py D [--K K] [--B B]   (D >= 1)')
    sys.stdout.write(scene(a.D, a.K, a.B))
