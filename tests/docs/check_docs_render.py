#!/usr/bin/env python3
"""Every Markdown page of the repository renders as written (issue: docs that
render): each table row has the header's number of cells, counted as GitHub's
renderer splits them (on every `|` not escaped as `\\|`, inside code spans
too), and no table row is left outside its table as raw text (cmark-gfm, the
renderer GitHub uses, with its table extension).
Usage: tests/docs/check_docs_render.py [REPO]; exit 1 naming each problem."""

import html.parser
import pathlib
import re
import subprocess
import sys


def cells(row):
    """A table row's cells, as GFM splits them."""
    row = row.strip()
    if row.startswith("|"):
        row = row[1:]
    if row.endswith("|") and not row.endswith("\\|"):
        row = row[:-1]
    return re.split(r"(?<!\\)\|", row)


DELIMITER = re.compile(r"^\s*\|?\s*:?-+:?\s*(\|\s*:?-+:?\s*)*\|?\s*$")


def table_problems(path):
    """Rows whose cell count differs from their table's header."""
    problems = []
    lines = path.read_text().splitlines()
    in_code = False
    i = 0
    while i < len(lines):
        line = lines[i]
        if line.lstrip().startswith("```"):
            in_code = not in_code
        elif not in_code and "|" in line and i + 1 < len(lines) and DELIMITER.match(lines[i + 1]):
            width = len(cells(line))
            if len(cells(lines[i + 1])) != width:
                problems.append(f"{path}:{i + 2}: the delimiter row has "
                                f"{len(cells(lines[i + 1]))} cells, the header {width}")
            i += 2
            while i < len(lines) and lines[i].strip() and "|" in lines[i]:
                n = len(cells(lines[i]))
                if n != width:
                    problems.append(f"{path}:{i + 1}: {n} cells, the header has {width} "
                                    "(an unescaped | inside a cell?)")
                i += 1
            continue
        i += 1
    return problems


class RawRows(html.parser.HTMLParser):
    """Paragraph text that looks like a table row: a table the renderer broke."""

    def __init__(self):
        super().__init__()
        self.in_p = False
        self.text = ""
        self.rows = []

    def handle_starttag(self, tag, attrs):
        if tag == "p":
            self.in_p, self.text = True, ""

    def handle_endtag(self, tag):
        if tag == "p" and self.in_p:
            self.in_p = False
            for line in self.text.splitlines():
                if line.strip().startswith("|") and line.count("|") >= 3:
                    self.rows.append(line.strip()[:80])

    def handle_data(self, data):
        if self.in_p:
            self.text += data


def render_problems(path):
    done = subprocess.run(["cmark-gfm", "-e", "table", str(path)], capture_output=True,
                          text=True, check=True)
    parser = RawRows()
    parser.feed(done.stdout)
    return [f"{path}: a table row renders as text: {row}" for row in parser.rows]


def main(argv):
    repo = pathlib.Path(argv[1] if len(argv) > 1 else pathlib.Path(__file__).parents[2])
    pages = sorted(repo.glob("docs/*.md")) + [repo / "README.md"] + sorted(
        repo.glob("*/**/README.md"))
    pages = [p for p in pages if "build" not in p.relative_to(repo).parts[0]]
    problems = []
    for page in pages:
        problems += table_problems(page) + render_problems(page)
    for p in problems:
        print(p)
    print(f"docs: {len(pages)} pages, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
