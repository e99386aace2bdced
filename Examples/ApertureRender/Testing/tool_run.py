"""One run of a command-line tool under test, for TestApertureRender.py and
TestAperturePrecompute.py.

In `make sanitize` LeakSanitizer's own tracer crashes now and then while it stops the threads of a
process that is ending ("Tracer caught signal 11 ... LeakSanitizer has encountered a fatal
error"): the leak check never ran, so that run says nothing of the program. A test that runs a
tool a hundred times meets it in most runs, too often for Testing/Sanitizers/ctest_sanitized.py's
one rerun of the whole test; such a run is made again here instead, and only such a run. A run
that changes what the next one finds (a cache it writes) gives `before`, which puts back what the
run expects before every try.
"""

import subprocess

TRACER = "LeakSanitizer has encountered a fatal error"
TRIES = 3


def run_tool(command, before=None, **kwargs):
    """subprocess.run(command, capture_output=True, timeout=600, **kwargs), once more (at most
    TRIES runs in all) while its stderr says that LeakSanitizer's tracer crashed; `before()`, if
    given, before every run."""
    for _ in range(TRIES):
        if before:
            before()
        result = subprocess.run(command, capture_output=True, timeout=600, **kwargs)
        err = result.stderr
        text = err.decode("utf-8", "replace") if isinstance(err, bytes) else err
        if TRACER not in text:
            break
    return result
