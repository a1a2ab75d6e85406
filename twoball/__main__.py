"""``python -m twoball``: the same program as the ``twoball`` console script."""

from twoball.verify.cli.main import main

raise SystemExit(main())
