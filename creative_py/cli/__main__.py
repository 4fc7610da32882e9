"""``python -m creative_py.cli``: the ``creative`` command."""

from creative_py.cli import main

main()
