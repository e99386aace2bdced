"""Runs every code block of README.md, as a reader would.

    python3 RunReadme.py <source folder> <build folder> <work folder>

- sh: each block as one bash script, in a work folder that links the source's Testing/ and the
  build folder as build/; `make TARGET` lines run as `make -n TARGET` in the source folder (this
  test runs inside `make test`, so the real commands would recurse);
- cpp and cmake: the C++ block as app.cxx and the CMake block as its CMakeLists.txt, configured
  against the build tree's ApertureLighting package, built, and run in the work folder;
- python: the Python block with the build's env.sh, in the work folder.
Any other block fails the test: every block must run. Each block must also leave the files its
commands name as output.
"""

import os
import re
import shutil
import subprocess
import sys

SOURCE, BUILD, WORK = (os.path.abspath(a) for a in sys.argv[1:4])
failures = []


def check(ok, what, detail=""):
    print(("ok   " if ok else "FAIL ") + what + ("" if ok else f": {detail}"))
    if not ok:
        failures.append(what)


def blocks(text):
    """(language, code) of every fenced block."""
    return re.findall(r"^```(\w*)\n(.*?)^```$", text, flags=re.M | re.S)


def environment():
    """The environment env.sh gives, for Python and the tools."""
    script = f". '{BUILD}/env.sh' && env -0"
    out = subprocess.run(["bash", "-c", script], capture_output=True, check=True).stdout
    return dict(item.split("=", 1) for item in out.decode().split("\0") if "=" in item)


def run(args, cwd, env, timeout=900):
    return subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)


def outputs(code):
    """The files a block's commands write: -o X, --save-data X, SetFileName("x") of writers."""
    names = re.findall(r"(?:-o|--save-data)\s+(\S+)", code)
    names += re.findall(r'writer\S*SetFileName\("([^"]+)"\)', code)
    return names


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
os.symlink(os.path.join(SOURCE, "Testing"), os.path.join(WORK, "Testing"))
os.symlink(BUILD, os.path.join(WORK, "build"))
env = environment()
with open(os.path.join(SOURCE, "README.md")) as f:
    found = blocks(f.read())
languages = [language for language, _ in found]
check(found and all(language in ("sh", "cpp", "cmake", "python") for language in languages),
      "every README block is sh, cpp, cmake or python", languages)

for number, (language, code) in enumerate(found):
    what = f"README block {number + 1} ({language})"
    if language == "sh":
        script = re.sub(r"^make (\w+)", rf"make -n -C '{SOURCE}' \1 > /dev/null", code, flags=re.M)
        result = run(["bash", "-e", "-c", script], WORK, env)
        check(result.returncode == 0, what + " runs", result.stderr[-2000:])
    elif language == "python":
        script = os.path.join(WORK, f"block{number + 1}.py")
        with open(script, "w") as f:
            f.write(code)
        result = run([sys.executable, script], WORK, env)
        check(result.returncode == 0, what + " runs", result.stderr[-2000:])
    elif language == "cmake":
        continue  # built with the C++ block
    elif language == "cpp":
        cmake = [c for lang, c in found if lang == "cmake"]
        check(len(cmake) == 1, what + " has its CMake block", len(cmake))
        project = os.path.join(WORK, "app")
        os.makedirs(project, exist_ok=True)
        with open(os.path.join(project, "app.cxx"), "w") as f:
            f.write(code)
        with open(os.path.join(project, "CMakeLists.txt"), "w") as f:
            f.write(cmake[0] if cmake else "")
        binary = os.path.join(project, "build")
        configure = run(["cmake", "-S", project, "-B", binary, "-DCMAKE_BUILD_TYPE=Release",
                         f"-DApertureLighting_DIR={BUILD}/lib/cmake/ApertureLighting"], WORK, env)
        build = run(["cmake", "--build", binary], WORK, env) if configure.returncode == 0 else None
        check(build is not None and build.returncode == 0, what + " and the CMake block build",
              (configure.stdout + configure.stderr)[-2000:] if build is None
              else (build.stdout + build.stderr)[-2000:])
        if build is not None and build.returncode == 0:
            result = run([os.path.join(binary, "app")], WORK, env)
            check(result.returncode == 0, what + " runs", result.stderr[-2000:])
    for name in outputs(code):
        check(os.path.exists(os.path.join(WORK, name)), f"{what} writes {name}")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
