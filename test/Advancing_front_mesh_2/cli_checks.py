"""What the command-line check scripts share: running a tool with an expected
exit code, and checks that are counted instead of stopping at the first."""
import os
import subprocess
import sys
import time

failures = []
timings = []  # (seconds, command) of every run


def check(condition, what):
    """Records `what` as failed when `condition` is false; the script goes on."""
    if not condition:
        failures.append(what)
        print("FAILED:", what)


def run(*args, code=0):
    """Runs a tool; stops the script when its exit code is not `code`."""
    start = time.monotonic()
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    timings.append((time.monotonic() - start, " ".join(os.path.basename(str(a)) for a in args)))
    if r.returncode != code:
        sys.exit("expected exit %d, got %d: %s\n%s%s" % (code, r.returncode, " ".join(map(str, args)), r.stdout,
                                                          r.stderr))
    return r


def finish(what):
    """Exits with the number of failed checks, or says that all passed."""
    # where a slow run's time goes (ctest keeps this output in its log)
    total = sum(t for t, _ in timings)
    print("%d runs took %.0f s; the slowest:" % (len(timings), total))
    for t, command in sorted(timings, reverse=True)[:12]:
        print("  %7.1f s  %s" % (t, command[:160]))
    if failures:
        sys.exit("%d check(s) failed" % len(failures))
    print(what + ": all checks passed")
