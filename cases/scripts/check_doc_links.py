#!/usr/bin/env python3
"""Check every relative link and #anchor in the repository's tracked Markdown files.

Usage: check_doc_links.py [ROOT]   (ROOT: the repository's top directory, default this script's)

For each tracked *.md file (`git ls-files`), every inline link or image `[text](target)` and
every reference definition `[label]: target` outside code spans and fenced code blocks is
checked, unless its target has a scheme (https:, mailto:, ...): the path, relative to the file
(or to ROOT when it starts with /), must be a tracked file or a directory holding one, and an
anchor (#name) into a Markdown file must be one of that file's heading anchors as GitHub makes
them (the heading's text without its Markdown, lower-cased, every character but letters, marks,
decimal digits, connector punctuation, spaces and hyphens removed, spaces turned into hyphens, a
repeated anchor suffixed -1, -2, ...) or an HTML id or name in it. Prints one line per broken
link, FILE:LINE: TARGET (why), and exits 1 when there is any; 0 when all resolve. Bad input: one
line, exit status 2.
"""
import os
import re
import subprocess
import sys
import unicodedata
from urllib.parse import unquote

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
ATX = re.compile(r"^ {0,3}(#{1,6})(?:[ \t]+(.*?))?[ \t]*#*[ \t]*$")
SETEXT = re.compile(r"^ {0,3}(=+|-+)[ \t]*$")
REF_DEF = re.compile(r"^ {0,3}\[([^\]]+)\]:[ \t]*<?([^\s>]+)>?")
HTML_ID = re.compile(r"""<[^>]*\b(?:id|name)\s*=\s*["']([^"']+)["']""", re.I)
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")


def fail(message):
    print("check_doc_links.py: " + message, file=sys.stderr)
    sys.exit(2)


def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True,
                             check=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        fail(f"{root}: cannot list its tracked files with git ({e})")
    return [p for p in out.decode("utf-8").split("\0") if p]


def blank_code(lines):
    """The lines with fenced code blocks blanked, so that nothing inside them is a heading or a
    link."""
    out, fence = [], None
    for line in lines:
        m = FENCE.match(line)
        if fence:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence):
                fence = None
            out.append("")
            continue
        if m:
            fence = m.group(1)
            out.append("")
            continue
        out.append(line)
    return out


def strip_code_spans(text):
    return re.sub(r"(`+)(.+?)\1", lambda m: " " * len(m.group(0)), text)


def heading_text(raw):
    """A heading's rendered text: code spans' contents kept, links' text kept, emphasis and
    HTML tags dropped."""
    text = re.sub(r"(`+)(.+?)\1", lambda m: m.group(2).strip(), raw)
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"<[^>]+>", "", text)
    text = re.sub(r"(\*+|(?<!\w)_+|_+(?!\w))", "", text)
    return text.strip()


def slug(text):
    kept = []
    for ch in text.lower():
        cat = unicodedata.category(ch)
        if cat[0] in "LM" or cat in ("Nd", "Pc") or ch in " -":
            kept.append(ch)
    return "".join(kept).replace(" ", "-")


def anchors_of(lines):
    """GitHub's heading anchors of a Markdown file, and its HTML ids and names."""
    found, seen = set(), {}
    code = blank_code(lines)
    for i, line in enumerate(code):
        raw = None
        m = ATX.match(line)
        if m:
            raw = m.group(2) or ""
        elif (SETEXT.match(line) and i > 0 and code[i - 1].strip() and not ATX.match(code[i - 1])
              and not code[i - 1].lstrip().startswith(("|", "-", "*", ">"))):
            raw = code[i - 1]
        if raw is not None:
            base = slug(heading_text(raw))
            n = seen.get(base, 0)
            found.add(base if n == 0 else f"{base}-{n}")
            seen[base] = n + 1
        for hid in HTML_ID.findall(line):
            found.add(hid)
    return found


def links_of(lines):
    """(line number, target) of every inline link, image and reference definition."""
    code = blank_code(lines)
    text = "\n".join(strip_code_spans(line) for line in code)
    starts = [0]
    for line in code:
        starts.append(starts[-1] + len(line) + 1)

    def line_of(offset):
        lo, hi = 0, len(starts) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if starts[mid] <= offset:
                lo = mid
            else:
                hi = mid - 1
        return lo + 1

    found = []
    # [text](target "title"): the text may span lines and hold brackets one level deep.
    for m in re.finditer(r"\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?([^)\s>]*)>?(?:\s+[\"'(][^)]*)?\)",
                         text):
        found.append((line_of(m.start(1)), m.group(1)))
    for i, line in enumerate(code):
        m = REF_DEF.match(line)
        if m:
            found.append((i + 1, m.group(2)))
    return found


def main(root):
    root = os.path.abspath(root)
    files = tracked_files(root)
    tracked = set(files)
    dirs = {os.path.dirname(p) for p in files}
    for d in list(dirs):
        while d:
            d = os.path.dirname(d)
            dirs.add(d)
    cache = {}

    def anchors(path):
        if path not in cache:
            with open(os.path.join(root, path), encoding="utf-8") as f:
                cache[path] = anchors_of(f.read().split("\n"))
        return cache[path]

    broken = []
    for md in sorted(p for p in files if p.endswith(".md")):
        try:
            with open(os.path.join(root, md), encoding="utf-8") as f:
                lines = f.read().split("\n")
        except (OSError, UnicodeDecodeError) as e:
            fail(f"{md}: cannot read it ({e})")
        for number, target in links_of(lines):
            if not target or SCHEME.match(target) or target.startswith("//"):
                continue
            path, _, anchor = target.partition("#")
            path = unquote(path)
            if path:
                base = root if path.startswith("/") else os.path.join(root, os.path.dirname(md))
                resolved = os.path.relpath(os.path.normpath(os.path.join(base, path.lstrip("/"))),
                                           root)
                if resolved.startswith(".."):
                    broken.append(f"{md}:{number}: {target} (outside the repository)")
                    continue
                resolved = "" if resolved == "." else resolved
                if resolved not in tracked and resolved not in dirs:
                    broken.append(f"{md}:{number}: {target} (no tracked file or directory "
                                  f"{resolved})")
                    continue
            else:
                resolved = md
            if anchor and resolved.endswith(".md") and resolved in tracked:
                if unquote(anchor) not in anchors(resolved):
                    broken.append(f"{md}:{number}: {target} (no heading #{anchor} in {resolved})")
    for line in broken:
        print(line)
    return 1 if broken else 0


if __name__ == "__main__":
    if len(sys.argv) > 2:
        fail("usage: check_doc_links.py [ROOT]")
    top = sys.argv[1] if len(sys.argv) == 2 else os.path.dirname(os.path.dirname(
        os.path.dirname(os.path.abspath(__file__))))
    if not os.path.isdir(top):
        fail(f"{top}: no such directory")
    sys.exit(main(top))
