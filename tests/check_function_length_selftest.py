#!/usr/bin/env python3
"""The length checks themselves (scripts/check_function_length.py): a class
of 301 lines fails and one of 300 passes, an enum of any length is not a
class, a function of 151 lines fails, and each failure names the file, the
line and the length. Run by ctest (check_function_length_selftest)."""
import pathlib
import subprocess
import sys
import tempfile

SCRIPT = pathlib.Path(__file__).resolve().parent.parent / "scripts" / "check_function_length.py"


def run(files):
    with tempfile.TemporaryDirectory() as d:
        root = pathlib.Path(d)
        for name, text in files.items():
            path = root / "src" / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        r = subprocess.run([sys.executable, str(SCRIPT), str(root)], capture_output=True,
                           text=True)
        return r.returncode, r.stderr


def class_of(lines, keyword="class", name="Big"):
    # header + body lines + closing brace: `lines` lines in all.
    body = "".join(f"  int m{i} = {i};\n" for i in range(lines - 3))
    return f"{keyword} {name} {{\n public:\n{body}}};\nint f() {{ return 0; }}\n"


def function_of(lines):
    body = "".join(f"  x += {i};\n" for i in range(lines - 3))
    return f"int g(int x) {{\n{body}  return x;\n}}\n"


def main():
    failures = []

    def expect(cond, what):
        if not cond:
            failures.append(what)

    code, err = run({"a.cpp": class_of(300)})
    expect(code == 0, f"a 300-line class passes (exit {code}: {err})")
    code, err = run({"a.cpp": class_of(301)})
    expect(code == 1 and "src/a.cpp:1: class Big is 301 lines" in err,
           f"a 301-line class fails, named (exit {code}: {err})")
    code, err = run({"b.h": class_of(400, "struct", "Wide")})
    expect(code == 1 and "class Wide is 400 lines" in err, f"a struct counts ({err})")
    enum = "enum class E {\n" + "".join(f"  e{i},\n" for i in range(400)) + "};\nint f() { return 0; }\n"
    code, err = run({"c.h": enum})
    expect(code == 0, f"an enum is not a class (exit {code}: {err})")
    code, err = run({"d.cpp": function_of(151) + class_of(10)})
    expect(code == 1 and "function g is 151 lines" in err, f"a 151-line function fails ({err})")
    code, err = run({"d.cpp": function_of(150) + class_of(10)})
    expect(code == 0, f"a 150-line function passes (exit {code}: {err})")
    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
