"""``python -m twoball``: the same program as the ``twoball`` console script."""

from twoball.cli.main import main

raise SystemExit(main())
