"""ctest for `make sanitize`: the suite, then again the tests that failed only because
LeakSanitizer's own tracer crashed while it stopped the process's threads at exit.

    ctest_sanitized.py CTEST_ARGUMENTS...     (in the build folder)

"Tracer caught signal 11 ... LeakSanitizer has encountered a fatal error" comes from tests that
pass alone (ptrace racing threads that are still ending): the process's leak check never ran, so
it says nothing of the test. Such tests run twice more; a test whose every run ends so (some do
under ctest every time, and pass when run by hand) runs a last time without the leak check,
AddressSanitizer and UndefinedBehaviorSanitizer still on, and says so. Any other failure fails
at once, without a rerun.
"""

import os
import re
import subprocess
import sys

TRACER = "LeakSanitizer has encountered a fatal error"
RERUNS = 2


def output_of(log, name):
    """A test's output in ctest's LastTest.log, or None."""
    match = re.search(r"Test: " + re.escape(name) + r"\n(.*?)\"" + re.escape(name) + r"\" end time",
                      log, re.S)
    return match.group(1) if match else None


def tracer_only():
    """The failed tests of the last ctest run if every one failed by the tracer's crash alone,
    else None."""
    with open("Testing/Temporary/LastTest.log", errors="replace") as f:
        log = f.read()
    with open("Testing/Temporary/LastTestsFailed.log") as f:
        failed = [line.split(":", 1)[1].strip() for line in f if ":" in line]
    if not failed or any(TRACER not in (output_of(log, name) or "") for name in failed):
        return None
    return failed


def without_leak_check():
    """The environment with LeakSanitizer's leak check off."""
    env = dict(os.environ)
    for key in ("ASAN_OPTIONS", "LSAN_OPTIONS"):
        options = [o for o in env.get(key, "").split(":") if o and not o.startswith("detect_leaks=")]
        env[key] = ":".join(options + ["detect_leaks=0"])
    return env


def main():
    args = sys.argv[1:]
    result = subprocess.run(["ctest", *args]).returncode
    for _ in range(RERUNS):
        if result == 0:
            return 0
        failed = tracer_only()
        if failed is None:
            return result
        print("Once more, after LeakSanitizer's tracer crashed: " + ", ".join(failed), flush=True)
        result = subprocess.run(["ctest", *args, "--rerun-failed"]).returncode
    if result == 0:
        return 0
    failed = tracer_only()
    if failed is None:
        return result
    print("Without the leak check, as LeakSanitizer's tracer crashed at every exit of: " +
          ", ".join(failed), flush=True)
    return subprocess.run(["ctest", *args, "--rerun-failed"], env=without_leak_check()).returncode


if __name__ == "__main__":
    sys.exit(main())
