#!/usr/bin/env python3
"""links_test.py ROOT [FILE...]: every relative link of the Markdown pages resolves.

Checks README.md and docs/*.md of ROOT (or the FILEs given): a link to a file or folder of the
tree must exist, and a link with #anchor must name a heading of its page (GitHub's rule: the
heading lower-cased, punctuation dropped, spaces to '-'). Web links (http:, https:, mailto:) are
not followed. Each broken link is printed as FILE:LINE: link: problem; exit 1 if any.
"""
import os
import re
import sys

LINK = re.compile(r'!?\[[^\]]*\]\(([^)\s]+)\)')
HEADING = re.compile(r'^(#{1,6})\s+(.*?)\s*#*\s*$')


def slug(heading):
    text = re.sub(r'`', '', heading).strip().lower()
    text = re.sub(r'[^\w\- ]', '', text)
    return text.replace(' ', '-')


def anchors_of(path, cache={}):
    if path not in cache:
        found, fenced = set(), False
        with open(path, encoding='utf-8') as f:
            for line in f:
                if line.startswith('```'):
                    fenced = not fenced
                    continue
                m = None if fenced else HEADING.match(line)
                if m:
                    base, n = slug(m.group(2)), 1
                    name = base
                    while name in found:  # GitHub numbers repeated headings: x, x-1, x-2
                        name, n = f'{base}-{n}', n + 1
                    found.add(name)
        cache[path] = found
    return cache[path]


def check(page):
    problems, fenced = [], False
    with open(page, encoding='utf-8') as f:
        lines = f.readlines()
    for number, line in enumerate(lines, 1):
        if line.startswith('```'):
            fenced = not fenced
            continue
        if fenced:
            continue
        for target in LINK.findall(line):
            if re.match(r'^[a-z]+:', target):
                continue
            path, _, anchor = target.partition('#')
            full = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(full):
                problems.append(f'{page}:{number}: {target}: no such file')
            elif anchor and full.endswith('.md') and anchor not in anchors_of(full):
                problems.append(f'{page}:{number}: {target}: no heading #{anchor} in {os.path.basename(full)}')
    return problems


def main():
    root = sys.argv[1]
    pages = sys.argv[2:] or [os.path.join(root, 'README.md')] + sorted(
        os.path.join(root, 'docs', name) for name in os.listdir(os.path.join(root, 'docs')) if name.endswith('.md'))
    problems = [p for page in pages for p in check(page)]
    for p in problems:
        print(p)
    if problems:
        print(f'links check: FAILED, {len(problems)} broken link(s) in {len(pages)} page(s)')
        return 1
    print(f'links check: every relative link of {len(pages)} page(s) resolves')
    return 0


if __name__ == '__main__':
    sys.exit(main())
