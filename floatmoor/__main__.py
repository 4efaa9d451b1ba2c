"""``python -m floatmoor``: the same as the ``floatmoor`` command."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
