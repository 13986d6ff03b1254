#!/usr/bin/env python3
"""Lists defaults written more than once: a member initialised to the same number under the same
name in more than one header (`int width = 256;` in seven option structs), which can drift apart.
Empty values (0, 1, -1) do not count: they say "unset", not a choice. The fix is one named
constant where the thing it configures lives, used by the others. Exits 1 if any."""
import collections
import re
import subprocess
import sys

MEMBER = re.compile(r'^\s+(?:static\s+)?(?:constexpr\s+)?[\w:<>]+\s+(\w+)\s*=\s*(-?[\d.]+(?:e[-+]?\d+)?f?)\s*;')
EMPTY = {'0', '0.0', '0.0f', '0.f', '1', '1.0', '1.0f', '-1', '-1.0', '-1.0f'}


def main():
    files = subprocess.check_output(
        ['git', 'ls-files', 'engine/*.h', 'tools/*.h', 'python/*.h']).decode().split()
    where = collections.defaultdict(set)
    for f in files:
        for line in open(f, encoding='utf-8', errors='replace'):
            m = MEMBER.match(line)
            if m and m.group(2) not in EMPTY and not m.group(1).startswith('k'):
                value = m.group(2).rstrip('f')
                where[(m.group(1), float(value))].add(f)
    bad = 0
    for (name, value), fs in sorted(where.items()):
        if len(fs) > 1:
            print(f'{name} = {value:g} is written in {len(fs)} headers: {", ".join(sorted(fs))}')
            bad += 1
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
