# SPDX-License-Identifier: MIT
"""Running a program with a time limit, measuring the CPU time of the whole command."""
import os
import signal
import subprocess
import threading
import time


def run(cmd, cwd, seconds, keep_stdout=False):
    """Runs cmd in cwd for at most `seconds`. Returns {code, stderr, wall, cpu}: code None when the
    time limit stopped it, negative for a signal; cpu the user + system seconds of the process and
    every child it waited for (os.wait4's rusage), so a multi-threaded render counts every thread.
    keep_stdout: also {stdout}."""
    start = time.monotonic()
    p = subprocess.Popen(cmd, cwd=cwd, stdin=subprocess.DEVNULL,
                         stdout=subprocess.PIPE if keep_stdout else subprocess.DEVNULL,
                         stderr=subprocess.PIPE, start_new_session=True)
    err, out = [], []
    readers = [threading.Thread(target=lambda: err.append(p.stderr.read()))]
    if keep_stdout:
        readers.append(threading.Thread(target=lambda: out.append(p.stdout.read())))
    for t in readers:
        t.start()
    timed_out = threading.Event()

    def stop():
        timed_out.set()
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass

    timer = threading.Timer(seconds, stop)
    timer.start()
    _, status, usage = os.wait4(p.pid, 0)
    timer.cancel()
    p.returncode = os.waitstatus_to_exitcode(status)
    for t in readers:
        t.join()
    p.stderr.close()
    result = {"code": None if timed_out.is_set() else p.returncode,
              "stderr": (err[0] if err else b"").decode(errors="replace"),
              "wall": time.monotonic() - start, "cpu": usage.ru_utime + usage.ru_stime}
    if keep_stdout:
        p.stdout.close()
        result["stdout"] = (out[0] if out else b"").decode(errors="replace")
    return result
