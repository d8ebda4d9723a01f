"""``python -m spinimpact`` runs the command line."""

from .cli import main

main()
