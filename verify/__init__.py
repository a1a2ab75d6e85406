"""twoball.verify -- cross-checks, studies, reports and the ``twoball`` command line."""
