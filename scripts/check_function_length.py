#!/usr/bin/env python3
"""Fail on a non-test C++ function longer than a limit (issue 14: "longest
non-test function under 150 lines").

Counts each function's lines from the first line of its declaration (its
template header or return type) to its closing brace, both included, blank
lines and comments too (what a reader scrolls through). Functions are found
by their braces, with comments, string and character literals and
preprocessor lines blanked first: a brace block at namespace or class scope
whose header has a parameter list is a function (a lambda inside a function
counts towards that function). A constructor's member initialisers
(`a_{x}`) are part of its header, not bodies of their own.

Scanned: src/, include/, apps/, bench/, python/ (C++ files); not tests
(*_test.cpp, tests/, fuzz/).

Classes too (issue 31: "no class over 300 lines"): a class, struct or union
body counts from its header's first line to its closing brace; --max-class
sets that limit (default 300), nested classes count on their own and inside
their enclosing class.

Usage: scripts/check_function_length.py [repo_root] [--max N] [--max-class C] [--list K]
  --max N        the function limit (default 150): exit 1 and one line per longer function
  --max-class C  the class limit (default 300): exit 1 and one line per longer class
  --list K       also print the K longest functions and classes
"""
import argparse
import pathlib
import re
import sys

SCANNED = ("src", "include", "apps", "bench", "python")
SUFFIXES = {".cpp", ".cc", ".h", ".hpp"}


def blank(text: str) -> str:
    """Comments, literals and preprocessor lines replaced by spaces; newlines
    kept so that line numbers stay."""
    out = []
    i, n = 0, len(text)
    line_start = True  # only whitespace since the last newline
    while i < n:
        c = text[i]
        if line_start and c == "#":
            # A preprocessor line, with its continuations.
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "/" and i + 1 < n and text[i + 1] == "/":
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if c == "/" and i + 1 < n and text[i + 1] == "*":
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        if c == "R" and i + 1 < n and text[i + 1] == '"' and (i == 0 or not (
                text[i - 1].isalnum() or text[i - 1] == "_")):
            # Raw string R"delim( ... )delim".
            open_paren = text.find("(", i + 2)
            delim = text[i + 2:open_paren]
            end = text.find(")" + delim + '"', open_paren)
            end = n if end < 0 else end + len(delim) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            line_start = False
            continue
        if c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):
            # A string or character literal (a ' after a digit or letter is
            # a digit separator, 1'000, or part of a prefix such as u8').
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (min(j, n - 1) + 1 - i))
            i = j + 1
            line_start = False
            continue
        out.append(c)
        if c == "\n":
            line_start = True
        elif not c.isspace():
            line_start = False
        i += 1
    return "".join(out)


TEMPLATE = re.compile(r"^\s*template\s*<")
CLASS = re.compile(r"^\s*(?:typedef\s+)?(?:class|struct|union|enum)\b")
NAMESPACE = re.compile(r"^\s*(?:inline\s+)?(?:namespace\b|extern\s*\s*$|extern\s+$)")
ACCESS = re.compile(r"^\s*(?:public|private|protected)\s*:(?!:)")


def strip_template(header: str) -> str:
    """The header without a leading template<...> (balanced)."""
    while TEMPLATE.match(header):
        start = header.index("<")
        depth = 0
        for k in range(start, len(header)):
            if header[k] == "<":
                depth += 1
            elif header[k] == ">":
                depth -= 1
                if depth == 0:
                    header = header[k + 1:]
                    break
        else:
            return header
    return header


def after_parameters(header: str):
    """The text after the first top-level (...) group, or None."""
    start = header.find("(")
    if start < 0:
        return None
    depth = 0
    for k in range(start, len(header)):
        if header[k] == "(":
            depth += 1
        elif header[k] == ")":
            depth -= 1
            if depth == 0:
                return header[k + 1:]
    return None


def has_initialisers(header: str) -> bool:
    rest = after_parameters(header)
    if rest is None:
        return False
    return re.match(r"^[\s\w]*:(?!:)", rest) is not None


CLASS_NAME = re.compile(r"\b(?:class|struct|union)\s+(?:\[\[[^\]]*\]\]\s*)?(?:alignas\s*\([^)]*\)\s*)?(\w+)")


def functions(text: str, classes=None):
    """Yields (name, first_line, last_line) of each function; appends
    (name, first_line, last_line) of each class, struct or union to
    `classes` when given (enums are not counted)."""
    src = blank(text)
    line_of = []
    line = 1
    for ch in src:
        line_of.append(line)
        if ch == "\n":
            line += 1
    # Stack of (kind, header_start, name); kind: scope (namespace, class,
    # file), function, inner (a block inside a function), init (a member
    # initialiser's braces).
    stack = [("scope", 0, "")]
    header_start = 0
    paren = 0
    for i, ch in enumerate(src):
        kind = stack[-1][0]
        if kind == "class":
            kind = "scope"
        if ch == "(":
            paren += 1
        elif ch == ")":
            paren -= 1
        elif ch == ";" and kind == "scope" and paren == 0:
            header_start = i + 1
        elif ch == "{":
            if kind != "scope" or paren > 0:
                stack.append(("inner", i, ""))
                continue
            header = src[header_start:i]
            header = ACCESS.sub(lambda m: " " * len(m.group()), header)
            bare = strip_template(header)
            prev = src[:i].rstrip()[-1:] if src[:i].strip() else ""
            if NAMESPACE.match(bare) or CLASS.match(bare):
                m = CLASS_NAME.match(bare.strip()) if CLASS.match(bare) else None
                if m and not re.match(r"^\s*(?:typedef\s+)?enum\b", bare):
                    start = header_start + (len(header) - len(header.lstrip()))
                    stack.append(("class", start, m.group(1)))
                else:
                    stack.append(("scope", i, ""))
                header_start = i + 1
            elif "(" in bare and has_initialisers(bare) and (prev.isalnum() or prev in "_>"):
                stack.append(("init", i, ""))
            elif "(" in bare:
                start = header_start + (len(header) - len(header.lstrip()))
                before = bare[:bare.find("(")].split()
                name = before[-1] if before else "?"
                stack.append(("function", start, name))
            else:
                stack.append(("inner", i, ""))
        elif ch == "}":
            if len(stack) == 1:
                continue  # unbalanced (a macro's brace); ignore
            kind, start, name = stack.pop()
            if kind == "function":
                yield name, line_of[start], line_of[i]
            if kind == "class" and classes is not None:
                classes.append((name, line_of[start], line_of[i]))
            if kind != "init" and stack[-1][0] in ("scope", "class"):
                header_start = i + 1


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("root", nargs="?", default=".")
    ap.add_argument("--max", type=int, default=150)
    ap.add_argument("--max-class", type=int, default=300)
    ap.add_argument("--list", type=int, default=0)
    args = ap.parse_args()
    root = pathlib.Path(args.root).resolve()
    found = []
    found_classes = []
    for top in SCANNED:
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in SUFFIXES or path.name.endswith("_test.cpp"):
                continue
            if "tests" in path.relative_to(root).parts:
                continue
            text = path.read_text(encoding="utf-8", errors="replace")
            classes = []
            for name, first, last in functions(text, classes):
                found.append((last - first + 1, str(path.relative_to(root)), first, name))
            for name, first, last in classes:
                found_classes.append((last - first + 1, str(path.relative_to(root)), first, name))
    found.sort(key=lambda f: (-f[0], f[1], f[2]))
    for length, path, first, name in found[:args.list]:
        print(f"{length:5d}  {path}:{first}  {name}")
    found_classes.sort(key=lambda f: (-f[0], f[1], f[2]))
    for length, path, first, name in found_classes[:args.list]:
        print(f"{length:5d}  {path}:{first}  class {name}")
    too_long = [f for f in found if f[0] > args.max]
    for length, path, first, name in too_long:
        print(f"{path}:{first}: function {name} is {length} lines, over the limit of {args.max}",
              file=sys.stderr)
    too_long_classes = [f for f in found_classes if f[0] > args.max_class]
    for length, path, first, name in too_long_classes:
        print(f"{path}:{first}: class {name} is {length} lines, over the limit of "
              f"{args.max_class}", file=sys.stderr)
    if not found:
        print("no functions found: wrong root?", file=sys.stderr)
        return 1
    return 1 if too_long or too_long_classes else 0


if __name__ == "__main__":
    sys.exit(main())
