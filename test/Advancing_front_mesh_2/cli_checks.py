"""What the command-line check scripts share: running a tool with an expected
exit code, and checks that are counted instead of stopping at the first."""
import subprocess
import sys

failures = []


def check(condition, what):
    """Records `what` as failed when `condition` is false; the script goes on."""
    if not condition:
        failures.append(what)
        print("FAILED:", what)


def run(*args, code=0):
    """Runs a tool; stops the script when its exit code is not `code`."""
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if r.returncode != code:
        sys.exit("expected exit %d, got %d: %s\n%s%s" % (code, r.returncode, " ".join(map(str, args)), r.stdout,
                                                          r.stderr))
    return r


def finish(what):
    """Exits with the number of failed checks, or says that all passed."""
    if failures:
        sys.exit("%d check(s) failed" % len(failures))
    print(what + ": all checks passed")
