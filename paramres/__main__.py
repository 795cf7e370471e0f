"""``python -m paramres``: the ``paramres`` command."""

import sys

from paramres.cli import main

if __name__ == "__main__":
    sys.exit(main())
