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
