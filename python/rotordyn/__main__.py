"""``python -m rotordyn ...`` is the ``rotordyn`` command (as ``python -m rotordyn.cli``)."""

import sys

from rotordyn.cli import main

sys.exit(main())
