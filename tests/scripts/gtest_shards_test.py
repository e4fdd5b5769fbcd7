"""scripts/gtest-shards on a stand-in test binary: every test the filter keeps runs exactly once and
an excluded one never; a failing test fails the run, and its shard and output are shown.

Usage: gtest_shards_test.py PATH/TO/scripts/gtest-shards
"""

import os
import subprocess
import sys
import tempfile

# A stand-in for a GoogleTest binary: 40 tests Suite.T0..T39, GoogleTest's filter (positive
# patterns, then '-' and negative ones, ':'-separated, '*' wildcards) and its sharding (test i
# runs in shard i mod total). It appends each test it runs to $RAN and fails Suite.T7 when
# $BREAK is set.
STAND_IN = r'''#!/usr/bin/python3
import fnmatch, os, sys
tests = ["Suite.T%d" % i for i in range(40)]
pattern = next((a.split("=", 1)[1] for a in sys.argv if a.startswith("--gtest_filter=")), "*")
positive, _, negative = pattern.partition("-")
def kept(name):
    return (any(fnmatch.fnmatchcase(name, p) for p in positive.split(":")) and
            not any(fnmatch.fnmatchcase(name, p) for p in negative.split(":") if p))
tests = [t for t in tests if kept(t)]
if "--gtest_list_tests" in sys.argv:
    print("Suite.")
    print("".join("  %s\n" % t.split(".")[1] for t in tests), end="")
    sys.exit(0)
total, index = int(os.environ["GTEST_TOTAL_SHARDS"]), int(os.environ["GTEST_SHARD_INDEX"])
failed = False
for i, test in enumerate(tests):
    if i % total != index:
        continue
    with open(os.environ["RAN"], "a") as ran:
        ran.write(test + "\n")
    if test == "Suite.T7" and os.environ.get("BREAK"):
        print("Suite.T7 failed here")
        failed = True
sys.exit(1 if failed else 0)
'''


def run(script, tests_dir, ran, extra_env):
    env = dict(os.environ, RAN=ran, **extra_env)
    return subprocess.run([sys.executable, script, "release", "--jobs", "2", "--tests-dir", tests_dir,
                           "--exclude", "Suite.T3*"], capture_output=True, text=True, env=env)


def main():
    script = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as root:
        tests_dir = os.path.join(root, "tests")
        os.makedirs(tests_dir)
        binary = os.path.join(tests_dir, "stand_in_tests")
        with open(binary, "w") as f:
            f.write(STAND_IN)
        os.chmod(binary, 0o755)
        # Suite.T3 and Suite.T30..T39 are excluded: 29 tests in ceil(29 / 15) = 2 shards.
        expected = sorted("Suite.T%d" % i for i in range(40) if not str(i).startswith("3"))

        ran = os.path.join(root, "ran-passing")
        passing = run(script, tests_dir, ran, {})
        tests_run = []
        if os.path.exists(ran):
            with open(ran) as f:
                tests_run = sorted(f.read().split())
        if passing.returncode != 0:
            failures.append("passing tests: exit %d\n%s" %
                            (passing.returncode, passing.stdout + passing.stderr))
        if tests_run != expected:
            failures.append("passing tests: ran %s, expected each of %s once" % (tests_run, expected))
        if "29 tests of 1 binaries in 2 shards" not in passing.stdout:
            failures.append("passing tests: no count of 29 tests in 2 shards:\n" + passing.stdout)

        # The negative control: one failing test fails the run, which shows its shard and output.
        broken = run(script, tests_dir, os.path.join(root, "ran-broken"), {"BREAK": "1"})
        if broken.returncode != 1:
            failures.append("a failing test: exit %d, expected 1" % broken.returncode)
        for fragment in ("FAILED: stand_in_tests shard", "Suite.T7 failed here", "1 shards failed"):
            if fragment not in broken.stdout:
                failures.append("a failing test: %r missing from:\n%s" % (fragment, broken.stdout))

        bad_jobs = subprocess.run([sys.executable, script, "release", "--jobs", "0", "--tests-dir",
                                   tests_dir], capture_output=True, text=True)
        if bad_jobs.returncode == 0 or "--jobs 0" not in bad_jobs.stderr:
            failures.append("--jobs 0: exit %d, stderr %r" % (bad_jobs.returncode, bad_jobs.stderr))
    for failure in failures:
        print("FAIL: " + failure)
    print("gtest-shards test: %d problem(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
