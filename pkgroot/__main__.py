"""``python -m linkrepro``: the same as the ``linkrepro`` command."""
import sys

from .harness.cli import main

sys.exit(main())
