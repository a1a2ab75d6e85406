"""twoball.cli -- the command line: argparse only, one module per subcommand.

Every flag name lives here; each subcommand builds the option objects of
:mod:`twoball` and calls one public verb.  ``main`` is the console script.
"""

__all__ = ["main"]
