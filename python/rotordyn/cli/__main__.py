"""``python -m rotordyn.cli ...`` is the ``rotordyn`` command."""

import sys

from rotordyn.cli import main

sys.exit(main())
