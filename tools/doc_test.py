#!/usr/bin/python3
"""Run a documentation page as a test: its decks written, its commands run, its shown output
compared with what the commands print.

    tools/doc_test.py PAGE.md --bin BUILD_DIR [--work DIR] [--rtol 0.02]

The page's fenced blocks, in order:
  ```toml file=NAME   (any language)   written to NAME in the work folder;
  ```sh               run there with bash -euo pipefail, BUILD_DIR first on PATH (so
                      `mpmx` is the build's) and the repository's tools/ as ./tools;
  ```text output      what the sh block before it prints: compared line by line, each
                      number within --rtol relatively (or 1e-9 absolutely) of the shown
                      one, every other word exactly; a line "..." skips lines up to the
                      next one that matches.
Exit 0 when every command succeeds and every output matches; 1 naming the first
difference; 2 on a page it cannot read.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(\S*)(.*)$")
NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?%?$")


def blocks(text):
    """(language, info, body) of every fenced block."""
    out, lines, i = [], text.splitlines(), 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m or not m.group(1):
            i += 1
            continue
        body, i = [], i + 1
        while i < len(lines) and not lines[i].startswith("```"):
            body.append(lines[i])
            i += 1
        out.append((m.group(1), m.group(2).strip(), "\n".join(body) + "\n"))
        i += 1
    return out


def same_word(shown, got, rtol):
    if NUMBER.match(shown) and NUMBER.match(got):
        a, b = float(shown.rstrip("%")), float(got.rstrip("%"))
        return abs(a - b) <= max(rtol * abs(a), 1e-9)
    return shown == got


def same_line(shown, got, rtol):
    s, g = shown.split(), got.split()
    return len(s) == len(g) and all(same_word(a, b, rtol) for a, b in zip(s, g))


def compare(shown, got, rtol):
    """None when `got` matches the shown output, else what differs."""
    want = [l for l in shown.splitlines() if l.strip()]
    have = [l for l in got.splitlines() if l.strip()]
    j = 0
    for k, line in enumerate(want):
        if line.strip() == "...":
            nxt = want[k + 1] if k + 1 < len(want) else None
            while nxt is not None and j < len(have) and not same_line(nxt, have[j], rtol):
                j += 1
            if nxt is None:
                j = len(have)
            continue
        if j >= len(have):
            return f"shown '{line}', but the output ended"
        if not same_line(line, have[j], rtol):
            return f"shown '{line}', printed '{have[j]}'"
        j += 1
    if j < len(have):
        return f"printed more than shown, from '{have[j]}'"
    return None


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("page")
    ap.add_argument("--bin", required=True, help="the build folder that holds mpmx")
    ap.add_argument("--work", help="the folder to run in (default: a new temporary one)")
    ap.add_argument("--rtol", type=float, default=0.02)
    a = ap.parse_args(argv)
    try:
        with open(a.page) as f:
            page = blocks(f.read())
    except OSError as e:
        print(f"doc_test: {e}", file=sys.stderr)
        return 2
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    work = a.work or tempfile.mkdtemp(prefix="mpmx_doc_")
    os.makedirs(work, exist_ok=True)
    if not os.path.exists(os.path.join(work, "tools")):
        os.symlink(os.path.join(repo, "tools"), os.path.join(work, "tools"))
    env = dict(os.environ, PATH=os.path.abspath(a.bin) + os.pathsep + os.environ.get("PATH", ""))
    last, ran, files = None, 0, 0
    for lang, info, body in page:
        m = re.search(r"file=(\S+)", info)
        if m:
            with open(os.path.join(work, m.group(1)), "w") as f:
                f.write(body)
            files += 1
        elif lang == "sh":
            p = subprocess.run(["bash", "-euo", "pipefail", "-c", body], cwd=work, env=env,
                               capture_output=True, text=True)
            if p.returncode != 0:
                print(f"doc_test: {a.page}: exit {p.returncode} from\n{body}{p.stdout}{p.stderr}", file=sys.stderr)
                return 1
            last, ran = p.stdout, ran + 1
        elif lang == "text" and info == "output":
            if last is None:
                print(f"doc_test: {a.page}: an output block before any command", file=sys.stderr)
                return 2
            why = compare(body, last, a.rtol)
            if why:
                print(f"doc_test: {a.page}: {why}\n--- printed:\n{last}", file=sys.stderr)
                return 1
    print(f"doc_test: {a.page}: {files} file(s) written, {ran} command block(s) run, every shown output matched"
          f" (in {work})")
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
