#!/usr/bin/env python3
"""Checks the relative links of Markdown files: the target file exists and, for `file#anchor`, the anchor is a
heading of that file (GitHub's slugs). Usage: scripts/check-links.py [FILE.md ...] (default: README.md, docs/*.md
and the top-level *.md files). Prints one line per broken link and exits 1 if there is one."""
import glob
import os
import re
import sys

LINK = re.compile(r'!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)')
FENCE = re.compile(r'^\s*```')


def slug(heading):
    text = re.sub(r'[^\w\- ]', '', heading.strip().lower())
    return text.replace(' ', '-')


def anchors(path):
    found, seen, fenced = set(), {}, False
    with open(path, encoding='utf-8') as f:
        for line in f:
            if FENCE.match(line):
                fenced = not fenced
            elif not fenced and line.startswith('#'):
                s = slug(line.lstrip('#'))
                n = seen.get(s, 0)
                seen[s] = n + 1
                found.add(s if n == 0 else f'{s}-{n}')
    return found


def links(path):
    fenced = False
    with open(path, encoding='utf-8') as f:
        for number, line in enumerate(f, 1):
            if FENCE.match(line):
                fenced = not fenced
                continue
            if fenced:
                continue
            for target in LINK.findall(re.sub(r'`[^`]*`', '', line)):
                if not re.match(r'^[a-z][a-z0-9+.-]*:', target):
                    yield number, target


def main(files):
    broken = 0
    for md in files:
        for number, target in links(md):
            name, _, anchor = target.partition('#')
            dest = os.path.normpath(os.path.join(os.path.dirname(md), name)) if name else md
            if not os.path.exists(dest):
                print(f'{md}:{number}: {target}: no such file {dest}')
                broken += 1
            elif anchor and dest.endswith('.md') and anchor not in anchors(dest):
                print(f'{md}:{number}: {target}: no heading #{anchor} in {dest}')
                broken += 1
    return 1 if broken else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:] or sorted(set(glob.glob('*.md') + glob.glob('docs/*.md')))))
