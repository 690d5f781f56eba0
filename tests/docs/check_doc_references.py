#!/usr/bin/python3
"""Every reference to the manual resolves.

Checks, over the source tree (src, tests, scripts, cases, postprocess, fuzz,
CMake files) and the manual itself (README.md, CHANGELOG.md, docs/**.md):
  - each `docs/PATH.md` or `README.md` named in code or a case file exists,
    and its `#anchor`, if any, is a heading of that page (GitHub's slugs);
  - no informal pointer into README by section name (README "X", README: X,
    README's X table): those went stale as the README changed; name the docs
    page and its anchor instead;
  - each relative Markdown link [text](path#anchor) in the manual resolves.
Prints every failure and exits 1 if there is one.

usage: check_doc_references.py SOURCE_DIR
"""
import pathlib
import re
import sys

CODE_FOLDERS = ["src", "tests", "scripts", "cases", "postprocess", "fuzz", ".ci"]
CODE_SUFFIXES = {".h", ".cpp", ".py", ".sh", ".toml", ".txt", ".j2", ".in", ""}
PATH_REF = re.compile(r"(?<![\w/.-])((?:docs/[\w./-]+\.md|README\.md))(#[\w-]+)?")
INFORMAL_README = re.compile(r"README(?!\.md)(?:\s*[,:]\s*|\s+)[\"'A-Za-z]")
MD_LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")


def slug(heading):
    text = heading.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(page):
    found, in_code = set(), False
    for line in page.read_text().splitlines():
        if line.startswith("```"):
            in_code = not in_code
        elif not in_code and line.startswith("#"):
            base = slug(line.lstrip("#"))
            name, n = base, 1
            while name in found:
                name, n = f"{base}-{n}", n + 1
            found.add(name)
    return found


def check_target(root, target, anchor, where, failures, cache):
    page = (root / target).resolve()
    if page.is_dir() and not anchor:
        return
    if not page.is_file():
        failures.append(f"{where}: {target} does not exist")
        return
    if anchor:
        if page not in cache:
            cache[page] = anchors(page)
        if anchor[1:] not in cache[page]:
            failures.append(f"{where}: {target} has no heading for {anchor}")


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    root = pathlib.Path(argv[1]).resolve()
    failures, cache = [], {}
    code = [p for folder in CODE_FOLDERS for p in (root / folder).rglob("*")
            if p.is_file() and p.suffix in CODE_SUFFIXES and "corpus" not in p.parts and "data" not in p.parts]
    code += [root / "CMakeLists.txt"]
    for path in code:
        try:
            text = path.read_text()
        except UnicodeDecodeError:
            continue
        for number, line in enumerate(text.splitlines(), 1):
            where = f"{path.relative_to(root)}:{number}"
            for target, anchor in PATH_REF.findall(line):
                if target in ("docs/PAGE.md", "docs/PATH.md"):  # placeholders in the rule's own wording
                    continue
                check_target(root, target, anchor, where, failures, cache)
            if INFORMAL_README.search(line) and path.name != pathlib.Path(__file__).name:
                failures.append(f"{where}: an informal pointer into README ({line.strip()[:80]}): name docs/PAGE.md#anchor")
    manual = [root / "README.md", root / "CHANGELOG.md"] + sorted((root / "docs").rglob("*.md"))
    for page in manual:
        if not page.is_file():
            continue
        for number, line in enumerate(page.read_text().splitlines(), 1):
            for link in MD_LINK.findall(line):
                if re.match(r"^[a-z]+:", link):
                    continue
                target, _, anchor = link.partition("#")
                where = f"{page.relative_to(root)}:{number}"
                if not target:
                    if anchor and anchor not in cache.setdefault(page.resolve(), anchors(page)):
                        failures.append(f"{where}: no heading for #{anchor}")
                    continue
                check_target(page.parent, target, "#" + anchor if anchor else "", where, failures, cache)
    for f in failures:
        print(f)
    print(f"{len(failures)} unresolved references")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
