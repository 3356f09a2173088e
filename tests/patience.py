"""How long a test waits for a child process before it calls it hung.

Far beyond any call's normal time (seconds; the first call in a fresh interpreter may compile
numba kernels, on a loaded 2-core machine several times slower than alone), so that no test's
verdict depends on how busy the machine is: a real hang still fails, only later.
"""
CHILD_SECONDS = 900.0
