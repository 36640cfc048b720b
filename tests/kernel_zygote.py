"""Jupyter kernels for the docs build of the test session (tests/docs_site.py,
which executes every notebook), forked from one process that has imported
what every kernel imports.

A fresh kernel process spends about 2.5 CPU s before the notebook's first
result: importing ipykernel and IPython, then the notebook's own imports
(SymPy, NumPy, mpmath, matplotlib, the package) and the library modules
their first computations load (SciPy's).  Here one process, the *zygote*,
imports these modules once, computes nothing, and forks a new
kernel for every notebook; each kernel is still a separate process with its
own fresh IPython kernel, namespace and caches, and runs every cell of its
notebook (its ``import`` statements included, which find the modules already
loaded, as a second import in a user's kernel does).

    python kernel_zygote.py serve SOCKET        the zygote (a Unix socket)
    python -I -S kernel_zygote.py client SOCKET CONNECTION_FILE

The client is the process jupyter_client starts as "the kernel" (the
kernelspec's argv): it asks the zygote for a kernel with its connection file,
working directory and environment, passes on the signals it receives
(interrupt, terminate) and exits with the kernel's exit status.  If the
client disappears (killed), the zygote kills its kernel.  The zygote reaps
its kernels, so their CPU time counts in the test process's children; it
ends, and ends its kernels, when the test process ends; a kernel ends when the
zygote does.

A kernel is only forked for the environment the zygote imported its modules
under (the package reads a few variables at import): a request whose
``LINECONTACT_SYM_*``, ``PYTHON*`` or ``MPLBACKEND`` variables differ is
refused, and the kernel fails to start rather than run with another set-up.
"""
import json
import os
import select
import signal
import socket
import sys

#: variables whose values at import time may change what the modules do
_SET_UP = ("LINECONTACT_SYM_", "PYTHON", "MPLBACKEND")


def _set_up(env: dict) -> dict:
    return {k: v for k, v in env.items() if k.startswith(_SET_UP)}


#: library modules that most notebooks' kernels import on their first
#: derivation, export or plot (measured: 0.6 CPU s a kernel); none of the
#: package's own modules beyond its top level, whose imports the notebooks make
_LIBRARIES = ("scipy.optimize", "scipy.special", "sympy.physics.units", "sympy.codegen.ast",
              "sympy.combinatorics", "sympy.tensor.tensor", "sympy.tensor.array.expressions",
              "sympy.sets.setexpr", "numpy.f2py", "numpy.testing", "numpy.polynomial", "numpy.random",
              "numpy.fft", "multiprocessing.connection", "multiprocessing.popen_fork",
              "matplotlib.backends.backend_agg", "PIL.features", "PIL.PngImagePlugin")


def _preload() -> None:
    import ipykernel.ipkernel  # noqa: F401
    import ipykernel.kernelapp  # noqa: F401
    import IPython  # noqa: F401
    import mpmath  # noqa: F401
    import numpy  # noqa: F401
    import sympy  # noqa: F401
    import linecontact_sym  # noqa: F401
    import importlib
    for name in _LIBRARIES:
        try:
            importlib.import_module(name)
        except ImportError:
            pass
    try:
        import matplotlib  # noqa: F401
        # pyplot (and its font list) without a backend: pyplot selects the backend at
        # its first figure, in the kernel (the inline one, set by _kernel, or MPLBACKEND's)
        import matplotlib.pyplot  # noqa: F401
    except ImportError:
        pass


def _kernel(request: dict) -> None:
    """In the forked child: become the kernel of ``request``; never returns."""
    code = 1
    try:
        for sig in (signal.SIGCHLD, signal.SIGTERM, signal.SIGINT):
            signal.signal(sig, signal.SIG_DFL)
        os.environ.clear()
        os.environ.update(request["env"])
        os.chdir(request["cwd"])
        if "numpy" in sys.modules:      # a fork shares its parent's NumPy seed; a fresh kernel draws its own
            sys.modules["numpy"].random.seed()
        if "matplotlib" in sys.modules and not os.environ.get("MPLBACKEND"):
            # a fresh kernel sets MPLBACKEND to the inline backend before its first import
            # of matplotlib, which reads it (ipykernel's init_gui_pylab); here matplotlib
            # was imported before: its backend is set as that import would have set it
            # (no figure was made in the zygote, so pyplot has selected no backend yet)
            sys.modules["matplotlib"].rcParams["backend"] = "module://matplotlib_inline.backend_inline"
        from ipykernel import kernelapp
        # the kernel ends when its parent does, as one the test started would (ipykernel
        # read JPY_PARENT_PID when the zygote imported it): its parent is the zygote
        sys.argv = [kernelapp.__file__, "-f", request["connection_file"],
                    f"--IPKernelApp.parent_handle={os.getppid()}"]
        try:
            kernelapp.IPKernelApp.launch_instance(argv=sys.argv[1:])
            code = 0
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
        import atexit
        atexit._run_exitfuncs()
    except BaseException:               # noqa: BLE001 -- reported, then the kernel ends
        import traceback
        traceback.print_exc()
    finally:
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except Exception:           # noqa: BLE001
                pass
        os._exit(code)


def serve(path: str) -> None:
    _preload()
    own = _set_up(dict(os.environ))
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(path)
    listener.listen(8)
    kernels: dict = {}                  # pid -> the client's connection
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(True))
    print("ready", flush=True)
    os.dup2(2, 1)                       # the kernels write where a kernel the test started would: not to the pipe
    parent = os.getppid()
    while not stop and os.getppid() == parent:     # the test process gone: so are the zygote and its kernels
        ready, _, _ = select.select([listener] + list(kernels.values()), [], [], 0.1)
        for s in ready:
            if s is listener:
                conn, _ = listener.accept()
                request = json.loads(conn.makefile("rb").readline())
                if _set_up(request["env"]) != own:
                    conn.sendall(b"refused: the kernel's environment is not the zygote's\n")
                    conn.close()
                    continue
                pid = os.fork()
                if pid == 0:
                    listener.close()
                    conn.close()
                    for c in kernels.values():
                        c.close()
                    _kernel(request)
                kernels[pid] = conn
                conn.sendall(f"{pid}\n".encode())
            else:
                pid = next(p for p, c in kernels.items() if c is s)
                line = s.recv(64)
                if not line:            # the client is gone: so is its kernel
                    _kill(pid)
                    continue
                for word in line.split():
                    if word.isdigit():
                        _kill(pid, int(word))
        while kernels:
            try:
                pid, status = os.waitpid(-1, os.WNOHANG)
            except ChildProcessError:
                break
            if pid == 0:
                break
            conn = kernels.pop(pid, None)
            if conn is not None:
                try:
                    conn.sendall(f"exit {os.waitstatus_to_exitcode(status)}\n".encode())
                except OSError:
                    pass
                conn.close()
    for pid in kernels:
        _kill(pid, signal.SIGKILL)
    for pid in list(kernels):
        try:
            os.waitpid(pid, 0)
        except ChildProcessError:
            pass
    listener.close()


def _kill(pid: int, sig: int = signal.SIGKILL) -> None:
    try:
        os.kill(pid, sig)
    except ProcessLookupError:
        pass


def client(path: str, connection_file: str) -> int:
    s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    s.connect(path)
    s.sendall(json.dumps({"connection_file": connection_file, "cwd": os.getcwd(),
                          "env": dict(os.environ)}).encode() + b"\n")
    answers = s.makefile("rb")
    first = answers.readline().decode()
    if not first.strip().isdigit():
        print(f"kernel_zygote: {first.strip() or 'no kernel'}", file=sys.stderr)
        return 1

    def relay(signum, frame):
        s.sendall(f"{signum}\n".encode())
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT):
        signal.signal(sig, relay)
    last = answers.readline().decode().split()
    if len(last) == 2 and last[0] == "exit":
        code = int(last[1])
        return code if code >= 0 else 128 - code
    return 1


if __name__ == "__main__":
    if sys.argv[1] == "serve":
        serve(sys.argv[2])
    else:
        sys.exit(client(sys.argv[2], sys.argv[3]))
