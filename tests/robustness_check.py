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
def scenario(name, v, L=1.0, rod=None, extra="", **particles):
    body = "".join(f"  {n}:\n    mass: {m!r}\n    gap: {g!r}\n" for n, (m, g) in particles.items())
    (work / f"{name}.yaml").write_text(f"name: {name}\nv: {v!r}\nL: {L!r}\n" + (f"rod: {rod}\n" if rod else "")
                                        + extra + "particles:\n" + body)
# issue 27: the causal rod, the rod's own view and the ledger figures at their extremes
scenario("m9", 0.1, A=(1e9, 0.5), B=(1e-9, 0.5))
scenario("m9fast", 0.9999999, A=(1e9, 0.5), B=(1e-9, 0.5))
scenario("m6pair", 0.01, A=(1e6, 0.5), B=(1e6, 0.5))
scenario("m6slow", 1e-6, A=(1e6, 0.5), B=(1e6, 0.5))
scenario("a4", 0.8, A=(4.0, 0.1))
scenario("a4g0", 0.8, A=(4.0, 0.0))
scenario("a4g3", 0.8, A=(4.0, 0.3))
scenario("b4", 0.8, B=(4.0, 0.1))
scenario("far", 0.6, A=(1.0, 1e4), B=(1.0, 1e4))
scenario("farslow", 0.01, A=(1.0, 1e6), B=(1.0, 0.5))
scenario("light15", 0.6, B=(0.0015, 0.5))
scenario("light13", 0.6, B=(0.0013, 0.5))
scenario("light1e9", 0.6, B=(1e-9, 0.5))
scenario("lightfast", 0.9999999, A=(1e-9, 0.5))
scenario("ss", 0.6, extra="sound_speed: 1\n", A=(1.0, 0.5))
scenario("heavy9", 0.6, A=(1e9, 0.5), B=(1e9, 0.5))
scenario("gap6", 0.6, A=(1.0, 0.5), B=(1.0, 1e6))
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
 # issue 27 (2): the causal run never ends
 "ledger fig2 --rod causal --v 0.9999999", "ledger fig2 --rod causal --v 0.9999999 --format json",
 "ledger fig1 --rod causal --v 0.9999999 --format csv", "export fig2 --rod causal --L 1e-100",
 "export fig1 --rod causal --L 1e-100 --format csv", "events fig2 --rod causal --L 1e100",
 "plot m9.yaml --rod causal", "ledger m9.yaml --rod causal", "events m6pair.yaml --rod causal",
 "events m6slow.yaml --rod causal", "ledger heavy9.yaml --rod causal", "events m9fast.yaml --rod causal",
 # (3) causal ledger figures from v = 0.97
 "ledger fig2 --rod causal --v 0.97 --format svg", "ledger fig2 --rod causal --v 0.99 --format svg",
 "ledger fig1 --rod causal --v 0.999 --format png", "ledger light1e9.yaml --rod causal --format svg",
 "ledger lightfast.yaml --rod causal --format pdf",
 # (4) animate --rod causal at high speed
 "animate fig2 --rod causal --v 0.999 --fps 4 --seconds 1", "animate fig2 --rod causal --v 0.9999999 --fps 4 --seconds 1",
 "animate fig1 --rod causal --v 0.99999 --fps 4 --seconds 1",
 "animate fig2 --rod causal --mode boost --frame rest..0.9999999 --fps 4 --seconds 1",
 "animate fig2 --rod causal --mode boost --frame -0.9999999..0.9999999 --fps 4 --seconds 1",
 # (5) the rod's own view at its extremes
 "plot fig2 --v 0.000001 --frame rod", "plot fig2 --v 0.000001 --frame rod --rod causal",
 "handout fig2 --v 0.000001 --frame rod", "animate fig2 --v 0.000001 --frame rod --fps 4 --seconds 1",
 "plot fig2 --v 5e-6 --frame both,rod", "plot gap6.yaml --frame rod", "plot gap6.yaml --frame rod --rod causal",
 "plot fig2 --L 1e-100 --frame rod --rod causal", "plot single --v 0.9999999 --rod causal",
 "plot single --v 0.9999999 --rod causal --frame rod", "plot fig1 --v 1e-6 --rod causal",
 # (6) wrong numbers
 "ledger fig1 --rod causal --L 1e-100 --frame rest", "ledger fig1 --rod causal --L 1e-60 --frame both",
 "export m9fast.yaml --rod causal",
 # (7) erratic "does not settle"
 "events a4.yaml --rod causal", "events a4g0.yaml --rod causal", "events a4g3.yaml --rod causal",
 "events b4.yaml --rod causal", "events fig2 --rod causal --v 0.95 --L 1e100", "events far.yaml --rod causal",
 "events farslow.yaml --rod causal",
 # (8) a light particle
 "events light15.yaml --rod causal", "events light13.yaml --rod causal", "events light1e9.yaml --rod causal",
 # (9) panels
 "plot fig2 --rod both --frame 0,0.1,0.2,0.3,0.4", "plot fig2 --frame rest,moving,0.1,0.2,0.3,0.4,0.5,0.6,rod",
 "plot fig2 --rod both --frame both,0.3,rod", "plot heavy9.yaml --frame both,rod", "handout heavy9.yaml --frame rod",
 # (10) wording
 "ledger fig2 --rod causal --L 1e-5", "events m9.yaml --rod causal", "handout m9.yaml --rod both",
 "plot ss.yaml --rod causal", "handout heavy9.yaml --rod both",
 # html (issue 27, item 1): a page never waits on a run it was not asked for, its cost bounded whatever v, L, masses
 "html heavy.yaml --v 0.6", "html heavy.yaml --v 0.1", "html heavy.yaml", "html mm.yaml", "html mm.yaml --v 0.05",
 "html fig2 --L 1e100 --rod both", "html fig2 --L 1e-100 --rod both", "html fig2 --v 0.9999999 --rod both",
 "html fig2 --v 0.9999999 --rod causal", "html single --v 0.9999999 --rod causal", "html fig1 --v 0.97 --rod both",
 "html fig2 --v 0.99 --rod both", "html gap.yaml --rod both", "html fig1 fig2 heavy.yaml --v 0.3",
]
ISSUE27 = cases.index("ledger fig2 --rod causal --v 0.9999999")
if len(sys.argv) > 2:  # only the cases containing this text ("27": only issue 27's)
    cases = cases[ISSUE27:] if sys.argv[2] == "27" else [c for c in cases if sys.argv[2] in c]
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
