#!/usr/bin/env python3
"""Checks that the commands stay thin over the engine's integrator (docs/design.md): no file under
tools/ or python/ constructs the GPU renderer, the CPU oracle's gather, or a CPU estimator that
runs beside the shading (clamping compensation, caustics) — engine/integrator does, once, for
render, convergence, bench, the preview and the Python module. Exits 1 with each offending line."""
import re
import subprocess
import sys

TYPES = r'(?:render::)?VplRenderer|(?:integrator::)?CpuEstimators|CpuEstimatorThread|' \
        r'(?:reference::)?ClampCompensation|(?:reference::)?CausticTracer'
CONSTRUCTS = [
    re.compile(r'make_(?:unique|shared)<\s*(?:' + TYPES + r')\s*>'),
    re.compile(r'\bnew\s+(?:' + TYPES + r')\b'),
    # a variable or member of the type itself (not a pointer or reference to one)
    re.compile(r'^\s*(?:const\s+)?(?:' + TYPES + r')\s+\w+\s*[({;=]'),
    re.compile(r'\bgather_vpls\s*\('),
]


def main():
    files = subprocess.check_output(
        ['git', 'ls-files', 'tools/*.cpp', 'tools/*.h', 'python/*.cpp', 'python/*.h']).decode().split()
    bad = 0
    for f in files:
        for n, line in enumerate(open(f, encoding='utf-8', errors='replace'), 1):
            code = line.split('//')[0]
            if any(p.search(code) for p in CONSTRUCTS):
                print(f'{f}:{n}: constructs what engine/integrator owns: {line.strip()}')
                bad += 1
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
