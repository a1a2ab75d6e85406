"""twoball.verify.reproduce -- the paper reproduction."""

__all__ = ["common", "contact", "driver", "icm", "cem"]
