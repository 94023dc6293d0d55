"""Run on demand (not by pytest): a new user's and an adversary's command lines -- extreme speeds, gaps and masses,
YAML 1.1 numbers, contradictory -o and --format, odd --at values, duplicates, an unwritable folder -- each in a
scratch folder under a 2 GiB address-space limit (prlimit) and a 60 s timeout. Each must either finish or be
refused in one sentence with exit status 1 or 2, with no traceback and nothing left in the temporary folder.

    python tests/robustness_check.py .venv/bin/sears-paradox
"""
import os, subprocess, sys, tempfile, time, signal, shutil
from pathlib import Path
TOOL = os.path.abspath(sys.argv[1]) if os.sep in sys.argv[1] else sys.argv[1]
work = Path(tempfile.mkdtemp(prefix="c15-"))
tmpdir = work / "tmp"; tmpdir.mkdir()
env = dict(os.environ, TMPDIR=str(tmpdir))
(work / "gap.yaml").write_text("name: gap\nv: 1.0e-6\nL: 1.0\nparticles:\n  A:\n    mass: 1.0\n    gap: 0.5\n  B:\n    mass: 1.0\n    gap: 1.0e+6\n")
(work / "heavy.yaml").write_text("name: heavy\nv: 0.9999999\nL: 1.0\nparticles:\n  A:\n    mass: 1.0e+9\n    gap: 0.5\n  B:\n    mass: 1.0e-9\n    gap: 0.5\n")
(work / "mm.yaml").write_text("name: mm\nv: 0.6\nL: 1.0\nparticles:\n  A:\n    mass: 1.0e-6\n    gap: 0.5\n  B:\n    mass: 1.0e+6\n    gap: 0.5\n")
(work / "sexa.yaml").write_text("name: sexa\nv: 0.6\nL: 1:30\nparticles:\n  A:\n    mass: 1.0\n    gap: 0.5\n")
ro = work / "ro"; ro.mkdir(); (ro / "x").write_text("")
cases = [
 "plot fig2 --v 0.9999999 --hyperbolae", "plot fig2 --v 0.999999 --hyperbolae", "plot fig1 --v 0.99999 --hyperbolae --light-cones",
 "plot while_turning --v 0.9999999 --hyperbolae --proper-time --rod-lines 50 --rod-now",
 "plot gap.yaml --proper-time", "plot fig2 --v 1e-6 --proper-time", "plot fig2 --v 1e-6 --proper-time --frame both,0.3,0.9,-0.5,0.6,-0.9",
 "plot gap.yaml --proper-time --frame both,0.3,0.9,-0.5,0.6,-0.9",
 "animate fig2 --v 1e-6 --mode boost --fps 4 --seconds 1", "animate fig1 --v 1e-5 --mode boost --fps 4 --seconds 1",
 "animate single --v 3e-7 --mode boost --fps 4 --seconds 1", "animate gap.yaml --fps 4 --seconds 1",
 "animate fig2 --fps 1000 --format mp4", "animate fig2 --fps 60 --seconds 120",
 "events fig2 --v 0.9999999 --frame-velocity 0.9999999", "export fig2 --v 0.9999999 --frame-velocity 0.9999999 --format json",
 "handout fig2 --v 0.9999999 --frame both,0.9999999",
 "ledger fig2 -o x.svg --format json", "ledger fig2 -o x.png --format text", "ledger fig2 -o x.pdf --format csv",
 "ledger fig2 -o x.tex --format svg", "ledger fig2 -o x.json --format markdown",
 "plot heavy.yaml", "animate heavy.yaml --fps 4 --seconds 1", "ledger heavy.yaml", "events heavy.yaml", "export heavy.yaml",
 "handout heavy.yaml",
 "events sexa.yaml", "plot sexa.yaml",
 "animate fig2 --format png --fps 4 --seconds 1 -o ro", "plot fig2 -o ro/a.svg", "handout fig2 -o /sys",
 "handout fig2 --v 0.9999999", "handout mm.yaml --format tex -o mmtex", "handout fig2 fig2", "handout fig1 fig2 fig1 --worksheet",
 "ledger fig2 --at 1_000", "ledger fig2 --at 0x10", "ledger fig2 --at 1e308", "ledger fig2 --at nan", "ledger fig2 --at inf",
 "plot fig2 --v 1", "plot fig2 --v 0.99999999999", "plot fig2 --L -1", "plot nosuch.yaml", "plot fig2 --frame 1",
 # html (issue 27, item 1): a page never waits on a run it was not asked for, its cost bounded whatever v, L, masses
 "html heavy.yaml --v 0.6", "html heavy.yaml --v 0.1", "html heavy.yaml", "html mm.yaml", "html mm.yaml --v 0.05",
 "html fig2 --L 1e100 --rod both", "html fig2 --L 1e-100 --rod both", "html fig2 --v 0.9999999 --rod both",
 "html fig2 --v 0.9999999 --rod causal", "html single --v 0.9999999 --rod causal", "html fig1 --v 0.97 --rod both",
 "html fig2 --v 0.99 --rod both", "html gap.yaml --rod both", "html fig1 fig2 heavy.yaml --v 0.3",
]
os.chmod(ro, 0o500)
bad = 0
for case in cases:
    before = set(os.listdir(tmpdir))
    t = time.time()
    try:
        p = subprocess.run(["prlimit", "--as=2147483648", "timeout", "60", TOOL, *case.split()], cwd=work, env=env,
                           capture_output=True, text=True, timeout=90)
        rc, out, err = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        rc, out, err = "TIMEOUT", "", ""
    dt = time.time() - t
    left = set(os.listdir(tmpdir)) - before
    lines = [l for l in err.splitlines() if l.strip()]
    ok = rc in (0, 1, 2) and "Traceback" not in err and not left and (rc == 0 and not lines or rc != 0 and len(lines) == 1)
    bad += not ok
    print(f"{'ok ' if ok else 'BAD'} {rc!s:>4} {dt:5.1f}s  {case}\n      {(lines[-1] if lines else out.strip()[:150])[:200]}" + (f"\n      left in tmp: {left}" if left else ""))
os.chmod(ro, 0o700)
shutil.rmtree(work, ignore_errors=True)
print("bad:", bad, "of", len(cases))
sys.exit(1 if bad else 0)
