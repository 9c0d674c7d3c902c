#!/usr/bin/env python3
"""Writes the N-device scene of issue 15: paper 000's Fig. 5 environment generalised to N contact
points on one virtual mass M (tied to ground by k, B; contact i through k_i, B_i), N 1-DOF
operators and N mass-damper devices (case ii: Gamma in G(N; 1, ..., 1)). Backward Euler, T = 0.01 s.

    E(s) = diag(k_i + B_i s) - c c^T / (M s^2 + (B + sum B_i) s + k + sum k_i),  c_i = k_i + B_i s

With --objects K (issue 39) the N devices split into K groups, each touching its own mass (E block
diagonal: the scene decomposes into K independent problems); with --delay D a network delay of D
samples ([delay]); with --chain C each object is the first of C equal masses in a chain (mass to
mass and the last to ground through k + B s): E has order 2C per object (`1 --chain 8`: the
one-DOF environment of order 16 of issue 39's table).

With --compact (one object) the scene says what is repeated (docs/scene.md, "Repeated blocks"): one
[[device]] and one [[operator]] with count = N, the contact values as list parameters kc, Bc and the
operator gains g, and E by its diagonal and off-diagonal entries: under 1 KB at N = 1024 (list parameters as
`{ repeat = [...], times = N/4 }`), where the written-out scene at N = 128 is 18 MB. The devices are then named d[1] .. d[N] (written out: d1 .. dN), the
operators H[1] .. H[N]; the models are the same.

Usage: bench/contact_scene.py N [--objects K] [--delay D] [--chain C] [--compact] > scene.toml
       build/hapstab multidof analyze --scene scene.toml
"""
import argparse
import sys

def scene(n, objects=1, delay=0, chain=1):
    out = ['[scene]', f'name = "case ii, {n} contact points on one mass"', 'T = "0.01"', '',
           '[parameters]', 'M = "0.3"', 'k = "1000"', 'B = "5"']
    for i in range(1, n + 1):
        out += [f'k{i} = "{500 + 100 * ((i - 1) % 4)}"', f'B{i} = "{["1", "2", "3/2", "5/2"][(i - 1) % 4]}"']
    out.append('')
    for i in range(1, n + 1):
        out += ['[[device]]', f'name = "d{i}"', 'm = "1/10"', 'b = "1.37"', '']
    for i in range(1, n + 1):
        gain = ["0.1", "0.05", "0.08", "0.06"][(i - 1) % 4]
        out += ['[[operator]]', f'name = "H{i}"', f'dofs = ["d{i}"]', f'tf = "{gain}*(s^2+5*s+10)/(s^2+s+1)"', '']
    obj = {i: (i - 1) * objects // n for i in range(1, n + 1)}  # object touched by device i
    # the masses behind the first one: mass j sees the link k + B s to the one before and after it
    # (the last: to ground); Y_j = M s^2 + 2 (k + B s) - (k + B s)^2 / Y_{j+1}, Y_C = M s^2 + 2 (k + B s)
    behind = behind_chain(chain)
    den = {o: ('(M*s^2 + (B' + ''.join(f'+B{i}' for i in range(1, n + 1) if obj[i] == o) + ')*s + k'
               + ''.join(f'+k{i}' for i in range(1, n + 1) if obj[i] == o)
               + (f' - (k + B*s)^2/({behind})' if behind else '') + ')') for o in range(objects)}
    rows = []
    for i in range(1, n + 1):
        ci = f'(k{i} + B{i}*s)'
        row = []
        for j in range(1, n + 1):
            cj = f'(k{j} + B{j}*s)'
            d = den[obj[i]]
            row.append('"0"' if obj[i] != obj[j] else
                       f'"k{i} + B{i}*s - {ci}^2/{d}"' if i == j else f'"-{ci}*{cj}/{d}"')
        rows.append('[' + ', '.join(row) + ']')
    out += ['[environment]', 'domain = "s"', 'method = "backward_euler"', 'tf = [' + ',\n      '.join(rows) + ']', '']
    if delay:
        out += ['[delay]', f'samples = "{delay}"', '']
    out += ['[multidof]', 'osp = [' + ', '.join(['"1.37"'] * n) + ']', 'qv_block_diagonal = false', '']
    out += ['[multidof.coupling]', 'mbar = [' + ', '.join(['1'] * n) + ']', 'nbar = [' + ', '.join(['1'] * n) + ']']
    return '\n'.join(out) + '\n'

def behind_chain(chain):
    """The masses behind the first one (see scene()): '' for a single mass."""
    behind = ''
    for _ in range(chain, 1, -1):
        behind = 'M*s^2 + 2*(k + B*s)' + (f' - (k + B*s)^2/({behind})' if behind else '')
    return behind

def compact_scene(n, delay=0, chain=1, objects=1):
    """scene(n, objects, delay, chain) with its repetition said once: E by its diagonal and
    off-diagonal entries, `blocks = K` for K objects (each of N/K devices, a multiple of 4, so
    that every object has the same contact sums SB, SK)."""
    ks = [str(500 + 100 * ((i - 1) % 4)) for i in range(1, n + 1)]
    bs = [["1", "2", "3/2", "5/2"][(i - 1) % 4] for i in range(1, n + 1)]
    gs = [["0.1", "0.05", "0.08", "0.06"][(i - 1) % 4] for i in range(1, n + 1)]
    # the values cycle through 4 kinds: said once with `repeat` when N is a multiple of 4
    lst = lambda v: ('{ repeat = [' + ', '.join(f'"{x}"' for x in v[:4]) + f'], times = {n // 4} }}' if n % 4 == 0 and n > 4
                     else '[' + ', '.join(f'"{x}"' for x in v) + ']')
    behind = behind_chain(chain)
    sums = ('sum(Bc)', 'sum(kc)') if objects == 1 else ('SB', 'SK')
    den = f'(M*s^2 + (B + {sums[0]})*s + k + {sums[1]}' + (f' - (k + B*s)^2/({behind})' if behind else '') + ')'
    per = n // objects
    where = 'one mass' if objects == 1 else f'{objects} masses'
    out = ['[scene]', f'name = "case ii, {n} contact points on {where}"', 'T = "0.01"', '',
           '[parameters]', 'M = "0.3"', 'k = "1000"', 'B = "5"',
           f'kc = {lst(ks)}', f'Bc = {lst(bs)}', f'g = {lst(gs)}']
    if objects > 1:  # each object's N/K contacts: N/(4K) of each of the 4 kinds
        out += [f'SB = "{per // 4}*(1 + 2 + 3/2 + 5/2)"', f'SK = "{per // 4}*(500 + 600 + 700 + 800)"']
    out += ['',
           '[[device]]', f'count = {n}', 'name = "d"', 'm = "1/10"', 'b = "1.37"', '',
           '[[operator]]', f'count = {n}', 'name = "H"', 'dofs = "d[i]"', 'tf = "g[i]*(s^2+5*s+10)/(s^2+s+1)"', '',
           '[environment]', 'domain = "s"', 'method = "backward_euler"',
           f'diagonal = "kc[i] + Bc[i]*s - (kc[i] + Bc[i]*s)^2/{den}"',
           f'off_diagonal = "-(kc[i] + Bc[i]*s)*(kc[j] + Bc[j]*s)/{den}"'] + ([f'blocks = {objects}'] if objects > 1 else []) + ['']
    if delay:
        out += ['[delay]', f'samples = "{delay}"', '']
    out += ['[multidof]', 'qv_block_diagonal = false']
    return '\n'.join(out) + '\n'

if __name__ == '__main__':
    ap = argparse.ArgumentParser(description='the contact scenes of issues 15 and 39')
    ap.add_argument('N', type=int, help='devices (1..256 written out, 1..4096 with --compact)')
    ap.add_argument('--objects', type=int, default=1, help='separate virtual objects (1..N)')
    ap.add_argument('--delay', type=int, default=0, help='network delay in samples')
    ap.add_argument('--chain', type=int, default=1, help='masses per object, in a chain (1..32)')
    ap.add_argument('--compact', action='store_true', help='say the repetition once (count, list parameters, blocks = K)')
    a = ap.parse_args()
    if not 1 <= a.N <= (4096 if a.compact else 256) or not 1 <= a.objects <= a.N or a.delay < 0 or not 1 <= a.chain <= 32:
        sys.exit('usage: bench/contact_scene.py N [--objects K] [--delay D] [--chain C] [--compact]   (1 <= K <= N <= 256, '
                 'N <= 4096 with --compact, D >= 0, 1 <= C <= 32)')
    if a.compact and a.objects != 1 and (a.N % a.objects or (a.N // a.objects) % 4):
        sys.exit('bench/contact_scene.py: --compact with --objects K needs N/K devices per object, a multiple of 4')
    sys.stdout.write(compact_scene(a.N, a.delay, a.chain, a.objects) if a.compact else scene(a.N, a.objects, a.delay, a.chain))
