"""Hostile CAD files: random mutations of the bundled STEP and IGES parts through the CLI.

    /usr/bin/python3 bench/mutate_cad.py build/bin/exactmat [--count 300] [--seed 1]

Each copy of Testing/Data/cad/bracket.step and l-prism.igs gets one to four mutations
(a digit changed, a byte replaced, up to 20 bytes cut, up to 40 bytes copied elsewhere)
and goes through `exactmat 3d FILE`. Every run must end with exit 0 (read and verified),
1 (refused with a message) or 3 (verification failed, said so), within 60 s: a crash or a
hang is printed with the file kept for a regression test.
"""
import argparse
import os
import random
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PARTS = [os.path.join(ROOT, "Testing", "Data", "cad", name) for name in ("bracket.step", "l-prism.igs")]


def mutate(data, rng):
    b = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        op, i = rng.random(), rng.randrange(len(b))
        if op < 0.4 and chr(b[i]).isdigit():
            b[i] = ord(rng.choice("0123456789"))
        elif op < 0.6:
            b[i] = rng.randrange(32, 127)
        elif op < 0.8:
            del b[i:i + rng.randint(1, 20)]
        else:
            j = rng.randrange(len(b))
            b[i:i] = b[j:j + rng.randint(1, 40)]
    return bytes(b)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("exactmat")
    parser.add_argument("--count", type=int, default=300)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    keep = tempfile.mkdtemp(prefix="exactmat-mutate-")
    outcomes = {}
    bad = 0
    for part in PARTS:
        data = open(part, "rb").read()
        ext = os.path.splitext(part)[1]
        for k in range(args.count):
            path = os.path.join(keep, "%s-%d%s" % (os.path.basename(part).split(".")[0], k, ext))
            with open(path, "wb") as f:
                f.write(mutate(data, rng))
            try:
                rc = subprocess.run([args.exactmat, "3d", path, "-o", os.path.join(keep, "out.vtp")],
                                    capture_output=True, timeout=60).returncode
            except subprocess.TimeoutExpired:
                rc = "hang"
            outcomes[rc] = outcomes.get(rc, 0) + 1
            if rc in (0, 1, 3):
                os.remove(path)
            else:
                bad += 1
                print("%s: exit %s" % (path, rc), flush=True)
    print("| files | exit 0 | exit 1 (refused) | exit 3 | crashed or hung |")
    print("|---:|---:|---:|---:|---:|")
    print("| %d | %d | %d | %d | %d |" % (sum(outcomes.values()), outcomes.get(0, 0), outcomes.get(1, 0),
                                          outcomes.get(3, 0), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    raise SystemExit(main())
