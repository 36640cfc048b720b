"""``python -m linecontact_sym`` runs the command line (see :mod:`linecontact_sym.cli`)."""
import sys

from .cli import main

sys.exit(main())
