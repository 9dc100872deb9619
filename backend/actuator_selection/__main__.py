"""``python -m actuator_selection``: see :mod:`actuator_selection.cli`."""

from actuator_selection.cli import main

raise SystemExit(main())
