"""``python -m linkrepro``: the same as the ``linkrepro`` command (same arguments, output and
exit status)."""
import sys

from .harness.cli import main

if __name__ == "__main__":
    sys.exit(main())
