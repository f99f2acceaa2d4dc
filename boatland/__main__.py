"""``python -m boatland`` is the ``boatland`` command."""

from boatland.cli import main

raise SystemExit(main())
