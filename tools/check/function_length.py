#!/usr/bin/env python3
"""Lists every function (C++ or GLSL) whose definition spans more than --max lines, signature to
closing brace; exits 1 if there is one. Brace matching on the text with comments, strings and
character literals blanked, so a lambda or a nested block counts towards its function."""
import argparse
import re
import subprocess
import sys

SCOPE = re.compile(r'^\s*(template\s*<.*>\s*)?(namespace|class|struct|union|enum|extern)\b')


def blank(text):
    """Comments, strings and character literals replaced by spaces, newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ' * (j - i))
            i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = ')' + (m.group(1) if m else '') + '"'
            j = text.find(end, i)
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r'[^\n]', ' ', text[i:j]))
            i = j
        elif c in '"\'' and not (c == "'" and i > 0 and text[i - 1].isalnum()):
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            out.append(' ' * (min(j + 1, n) - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def long_functions(path, limit):
    text = blank(open(path, encoding='utf-8', errors='replace').read())
    # Preprocessor lines (with their continuations) blanked too.
    text = re.sub(r'(?m)^[ \t]*#(?:[^\n]*\\\n)*[^\n]*', lambda m: re.sub(r'[^\n]', ' ', m.group(0)), text)
    stack = []  # (kind, start line)
    head_start = 0  # offset of the text since the last ; { or }
    line = 1
    found = []
    for i, c in enumerate(text):
        if c == '\n':
            line += 1
        elif c in ';':
            head_start = i + 1
        elif c == '{':
            head = text[head_start:i]
            outer = all(k != 'function' and k != 'other' for k, _ in stack)
            if SCOPE.match(head.strip()) or head.strip() == '':
                kind = 'scope' if SCOPE.match(head.strip()) else 'other'
            elif outer and ')' in head and '=' not in head.split('(')[0]:
                kind = 'function'
            else:
                kind = 'other'
            # A function's first line is its signature's.
            first = line - len(head.strip().split('\n')) + 1 if kind == 'function' else line
            stack.append((kind, first))
            head_start = i + 1
        elif c == '}':
            if stack:
                kind, first = stack.pop()
                if kind == 'function' and line - first + 1 > limit:
                    found.append((line - first + 1, first))
            head_start = i + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument('--max', type=int, default=80)
    parser.add_argument('files', nargs='*')
    args = parser.parse_args()
    files = args.files or subprocess.check_output(
        ['git', 'ls-files', '*.cpp', '*.h', '*.glsl', '*.comp', '*.vert', '*.frag']).decode().split()
    bad = 0
    for f in files:
        for n, first in long_functions(f, args.max):
            print(f'{f}:{first}: function of {n} lines (at most {args.max})')
            bad += 1
    print(f'{bad} functions over {args.max} lines', file=sys.stderr)
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
