"""Strict JSON text: NaN and infinities as null, array and scalar types of numpy as Python's.

Every JSON twoball writes (``--json`` on standard output, ``results.json``,
provenance files) goes through :func:`json_text`, so a reader in any language
gets standard JSON.  Only the standard library is used: numpy values are
recognised by their ``tolist`` method.
"""

from __future__ import annotations

import json
import math
from typing import Any

__all__ = ["clean_json", "json_text"]


def clean_json(value: Any) -> Any:
    """Replace NaN/inf by None and numpy scalars/arrays by Python values (strict JSON)."""
    if isinstance(value, dict):
        return {str(k): clean_json(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [clean_json(v) for v in value]
    if not isinstance(value, (str, bytes, int, float)) and hasattr(value, "tolist"):
        return clean_json(value.tolist())  # numpy array or scalar
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    return value


def json_text(data: Any) -> str:
    """Strict JSON (two-space indent, NaN as null) with a trailing newline."""
    return json.dumps(clean_json(data), indent=2, allow_nan=False) + "\n"
