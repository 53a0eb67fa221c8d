#!/usr/bin/env python3
"""The .cpp files of src/ that clang-tidy must check (tests/lint_checks.sh), one a line on stdout.

clang-tidy checks each file on its own, from the file and what it includes: a file whose own text,
project headers (src/), flags, checks and clang-tidy are those of a tree that passed in full gives the
same findings again, none. tests/lint_clean_at names such a tree (a commit) and the clang-tidy that
checked it. Printed:

- every file (but src/web/ and src/python/, which this build does not compile) with --all, or when
  the record is missing, names a commit this tree does not descend from (a shallow clone), names
  another clang-tidy, or when anything that every file's checks depend on changed since it: the
  checks (.clang-tidy), the lint scripts, the build's flags (the top CMakeLists.txt, src/'s CMake
  files, the presets, cmake/, third_party/);
- otherwise the files that changed since that commit (committed or not, untracked included) and the
  files that include a changed header, directly or through other headers of src/.

Why it printed what it did goes to stderr. --record writes tests/lint_clean_at for HEAD (after a full
pass on a clean tree: tests/lint_checks.sh --all does it). --self-test checks the selection on a
throwaway repository.
"""
import os
import re
import subprocess
import sys
import tempfile

RECORD = "tests/lint_clean_at"
SKIPPED = ("src/web/", "src/python/")
# A change to any of these can change every file's findings.
EVERYTHING = (".clang-tidy", "tests/lint_checks.sh", "tests/lint_files.py", "CMakePresets.json", "third_party/",
              "cmake/")
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.MULTILINE)


def git(*args, check=True):
    return subprocess.run(["git", *args], capture_output=True, text=True, check=check)


def tidy_version():
    try:
        out = subprocess.run(["clang-tidy", "--version"], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return "unknown"
    lines = [line.strip() for line in out.splitlines() if "version" in line.lower()]
    return lines[0] if lines else "unknown"


def all_sources():
    found = []
    for root, _, files in os.walk("src"):
        for name in files:
            path = os.path.join(root, name).replace(os.sep, "/")
            if path.endswith(".cpp") and not path.startswith(SKIPPED):
                found.append(path)
    return sorted(found)


def includers(changed):
    """Every file of src/ that is in `changed` or includes one of them, through src/'s headers."""
    included_by = {}
    for root, _, files in os.walk("src"):
        for name in files:
            path = os.path.join(root, name).replace(os.sep, "/")
            if not path.endswith((".h", ".hpp", ".cpp", ".inc")):
                continue
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            for target in INCLUDE.findall(text):
                # Project includes are written from src/ ("render/gl_renderer.h") or beside the file.
                for candidate in ("src/" + target, os.path.normpath(os.path.join(root, target)).replace(os.sep, "/")):
                    included_by.setdefault(candidate, set()).add(path)
    reached, todo = set(changed), list(changed)
    while todo:
        for parent in included_by.get(todo.pop(), ()):
            if parent not in reached:
                reached.add(parent)
                todo.append(parent)
    return reached


def read_record():
    try:
        with open(RECORD, encoding="utf-8") as f:
            fields = dict(line.split(" ", 1) for line in f.read().splitlines() if line and not line.startswith("#"))
        return fields["commit"].strip(), fields["clang-tidy"].strip()
    except (OSError, KeyError, ValueError):
        return None, None


def selection(everything):
    sources = all_sources()
    if everything:
        return sources, "every file (--all)"
    commit, version = read_record()
    if not commit:
        return sources, f"every file: {RECORD} is missing or unreadable"
    if version != tidy_version():
        return sources, f"every file: {RECORD} was checked by '{version}', this is '{tidy_version()}'"
    if git("merge-base", "--is-ancestor", commit, "HEAD", check=False).returncode != 0:
        return sources, f"every file: this tree does not descend from {commit} (or the clone lacks it)"
    changed = set(git("diff", "--name-only", commit).stdout.split())
    changed |= set(git("ls-files", "--others", "--exclude-standard").stdout.split())
    for path in sorted(changed):
        build_file = path == "CMakeLists.txt" or (path.startswith("src/") and
                                                  (path.endswith("/CMakeLists.txt") or path.endswith(".cmake")))
        if path.startswith(EVERYTHING) or build_file:
            return sources, f"every file: {path} changed since {commit[:12]}"
    reached = includers({p for p in changed if p.startswith("src/")})
    picked = [s for s in sources if s in reached]
    return picked, f"{len(picked)} of {len(sources)} files: those changed since {commit[:12]} (clean in full) or including a changed header"


def record():
    if git("status", "--porcelain", "--untracked-files=no").stdout.strip():
        sys.exit("lint_files.py --record: the tree has uncommitted changes; record a committed tree")
    head = git("rev-parse", "HEAD").stdout.strip()
    with open(RECORD, "w", encoding="utf-8") as f:
        f.write("# The last commit whose src/ passed clang-tidy in full (tests/lint_checks.sh --all), and the\n"
                "# clang-tidy that checked it: tests/lint_files.py checks only what changed since.\n"
                f"commit {head}\nclang-tidy {tidy_version()}\n")
    print(f"lint_files.py: recorded {head} in {RECORD}; commit it", file=sys.stderr)


def self_test():
    here = os.path.abspath(__file__)
    with tempfile.TemporaryDirectory() as repo:
        os.chdir(repo)
        git("init", "-q")
        git("config", "user.email", "t@t")
        git("config", "user.name", "t")
        files = {"src/a/base.h": "int base();\n", "src/a/mid.h": '#include "a/base.h"\n',
                 "src/a/base.cpp": '#include "a/base.h"\n', "src/b/user.cpp": '#include "a/mid.h"\n',
                 "src/b/other.cpp": "int other();\n", "src/web/page.cpp": '#include "a/base.h"\n',
                 ".clang-tidy": "Checks: '-*'\n"}
        for path, text in files.items():
            os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        git("add", "-A")
        git("commit", "-q", "-m", "one")
        os.makedirs("tests")
        assert selection(False)[0] == ["src/a/base.cpp", "src/b/other.cpp", "src/b/user.cpp"], "no record: all"
        record()
        git("add", "-A")
        git("commit", "-q", "-m", "recorded")
        assert selection(False)[0] == [], "nothing changed: nothing to check"
        with open("src/a/base.h", "a", encoding="utf-8") as f:
            f.write("int more();\n")
        assert selection(False)[0] == ["src/a/base.cpp", "src/b/user.cpp"], "a header: its includers, through mid.h"
        git("commit", "-q", "-am", "header")
        assert selection(False)[0] == ["src/a/base.cpp", "src/b/user.cpp"], "committed, the same"
        with open("src/b/new.cpp", "w", encoding="utf-8") as f:
            f.write("int n();\n")
        assert "src/b/new.cpp" in selection(False)[0], "an untracked file is checked"
        with open(".clang-tidy", "a", encoding="utf-8") as f:
            f.write("# changed\n")
        assert len(selection(False)[0]) == 4, "the checks changed: every file"
        git("checkout", "-q", ".clang-tidy")
        with open(RECORD, "w", encoding="utf-8") as f:
            f.write("commit 0123456789abcdef0123456789abcdef01234567\nclang-tidy " + tidy_version() + "\n")
        assert len(selection(False)[0]) == 4, "a commit this tree lacks: every file"
    print("lint_files.py: self-test passed (" + here + ")")


def main():
    args = sys.argv[1:]
    if args == ["--self-test"]:
        self_test()
        return
    if args == ["--record"]:
        record()
        return
    if args not in ([], ["--all"]):
        sys.exit("usage: lint_files.py [--all | --record | --self-test]")
    picked, why = selection(args == ["--all"])
    print(f"lint_files.py: {why}", file=sys.stderr)
    for path in picked:
        print(path)


if __name__ == "__main__":
    main()
