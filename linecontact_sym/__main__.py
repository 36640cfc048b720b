"""``python -m linecontact_sym`` runs the command line (see :mod:`linecontact_sym.cli`).

Importing this module runs nothing: Sphinx's autosummary imports every module
of the package to list it, and an import that called ``sys.exit(main())``
parsed the build's own arguments and ended it ("invalid choice: '-q'")."""
import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
