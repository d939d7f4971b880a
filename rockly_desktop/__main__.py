"""``python -m rockly_desktop``: the same as the ``rockly`` command."""
import sys

from rockly_desktop.cli import main

sys.exit(main())
