"""twoball.verify.fit -- model parameters fitted to measured rows (``twoball fit``).

``data`` reads a measured CSV file and refuses it by file, row and column;
``models`` predicts its measured columns row by row (the closed-form lift-off,
the whole bounce); ``solve`` fits the parameters by least squares with standard
errors from the Jacobian (and a bootstrap); ``result`` holds the answer
(:class:`~twoball.verify.fit.result.FitResult`, the JSON and the figure).
"""

__all__ = ["data", "models", "result", "solve"]
