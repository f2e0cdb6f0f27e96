#!/usr/bin/env python3
"""The acceptance suite: for each capability a resolved issue promised users, a check that runs
the dinam program as a user would and checks the figure the issue named.

  tests/acceptance/run.py build/dinam            every promise, one line each, and a count
  tests/acceptance/run.py build/dinam NAME...    those promises (modes.chain_sways, ...)
  tests/acceptance/run.py --list                 their names, one a line (CTest adds one test each)

Each promise runs in a fresh temporary folder, removed afterwards. Exit 0 when every promise
asked for holds."""
import importlib
import sys
import tempfile
import traceback
from pathlib import Path


sys.path.insert(0, str(Path(__file__).resolve().parent))
from promise import PROMISES, Broken, Run  # noqa: E402

# One file per capability, each holding its promises; every file here but this one and the
# harness.
HERE = Path(__file__).resolve().parent
CAPABILITIES = sorted(p.stem for p in HERE.glob("*.py") if p.stem not in ("run", "promise"))


def main(arguments):
    for capability in CAPABILITIES:
        importlib.import_module(capability)
    if arguments == ["--list"]:
        print("\n".join(PROMISES))
        return 0
    if not arguments:
        print(__doc__)
        return 2
    program = Path(arguments[0]).resolve()
    if not program.is_file():
        print(f"acceptance: no program at {arguments[0]} (build it first)")
        return 2
    names = arguments[1:] or list(PROMISES)
    unknown = [n for n in names if n not in PROMISES]
    if unknown:
        print(f"acceptance: no promise named {', '.join(unknown)} (--list names them)")
        return 2
    held = 0
    for name in names:
        issue, text, check = PROMISES[name]
        with tempfile.TemporaryDirectory(prefix=f"acceptance-{name}-") as folder:
            try:
                figure = check(Run(program, folder))
                held += 1
                print(f"ok    {name} (issue {issue}: {text}): {figure}", flush=True)
            except Broken as broken:
                print(f"FAIL  {name} (issue {issue}: {text}): {broken}", flush=True)
            except Exception:  # a check that cannot run is broken too, with its trace
                print(f"FAIL  {name} (issue {issue}: {text}): the check itself failed:\n"
                      f"{traceback.format_exc()}", flush=True)
    print(f"acceptance: {held} held, {len(names) - held} failed")
    return 0 if held == len(names) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
