"""common.py - what every module of the driver shares: the one-line error
(Failure), a shell command's first line (sh) and a file written whole
(write). Imports no other module of the driver."""
import os
import subprocess


class Failure(Exception):
    """A one-line error: `bench: MESSAGE`, exit status CODE."""
    def __init__(self, msg, code=1):
        super().__init__(msg)
        self.code = code


def sh(cmd):
    """A shell command's first line of output ('' when it fails)."""
    try:
        out = subprocess.run(cmd, shell=True, capture_output=True, text=True).stdout
    except OSError:
        return ""
    return out.split("\n")[0].strip()


def write(path, lines):
    tmp = f"{path}.tmp.{os.getpid()}"
    with open(tmp, "w") as f:
        f.write("".join(l + "\n" for l in lines))
    os.rename(tmp, path)


def gnuplot_fig(R, P, fig):
    """Draws scripts/fig-FIG.gp from P/fig-FIG.vars.gp into R/fig-FIG.png
    (written whole or not at all); its log in P/gnuplot-FIG.log."""
    gpdir = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = f"{R}/.fig-{fig}.png.tmp.{os.getpid()}"
    with open(f"{P}/gnuplot-{fig}.log", "w") as log:
        rc = subprocess.run(["gnuplot", "-e", f"VARS='{P}/fig-{fig}.vars.gp'; OUT='{out}'",
                             f"{gpdir}/fig-{fig}.gp"], stdout=subprocess.DEVNULL, stderr=log).returncode
    if rc != 0:
        first = next((l.strip() for l in open(f"{P}/gnuplot-{fig}.log") if l.strip()), "")
        if os.path.exists(out):
            os.remove(out)
        raise Failure(f"gnuplot failed on scripts/fig-{fig}.gp: {first}")
    if not os.path.isfile(out) or os.path.getsize(out) == 0:
        raise Failure(f"scripts/fig-{fig}.gp wrote no image")
    os.rename(out, f"{R}/fig-{fig}.png")
