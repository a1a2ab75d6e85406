"""Table 1 of the paper (§4) and its ICM columns recomputed from eq. (2.6).

The printed ICM columns are ``v / |v0|`` (see :mod:`twoball.modal.icm`);
:func:`table1_check` rounds ours to the printed two significant figures and
compares, fitting nothing.
"""

from __future__ import annotations

from dataclasses import dataclass

from twoball._common.errors import ParameterError
from twoball._common.keywords import checked
from twoball.modal.icm.limits import touching_ratios

#: Significant figures of the ICM columns in Table 1.
TABLE1_DIGITS = 2


@dataclass(frozen=True)
class Table1Row:
    """One row of Table 1 (§4), values as printed.

    Attributes
    ----------
    lower, upper : str
        The lower and upper body.
    mu, e2, e12 : float
        Mass ratio and restitution coefficients.
    measured_v1, icm_v1 : float
        Measured upper-ball rebound ratio and the printed ICM value.
    measured_v2, icm_v2 : float
        Measured lower-ball rebound ratio and the printed ICM value.

    Notes
    -----
    The header says the ratios are ``v / |u0|``; the printed ICM values are in
    fact ``v / |v0|`` (see the module docstring).
    """

    lower: str
    upper: str
    mu: float
    e2: float
    e12: float
    measured_v1: float
    icm_v1: float
    measured_v2: float
    icm_v2: float


#: Table 1 of the paper, all six rows in printed order.
TABLE1: tuple[Table1Row, ...] = (
    Table1Row("Tennis", "Coin", 0.062, 0.83, 0.46, 1.6, 1.5, 0.69, 0.67),
    Table1Row("Tennis", "Nut", 0.035, 0.83, 0.41, 1.5, 1.5, 0.74, 0.74),
    Table1Row("Tennis", "Table tennis", 0.050, 0.83, 0.59, 1.5, 1.8, 0.77, 0.69),
    Table1Row("Basketball", "Tennis", 0.101, 0.80, 0.89, 1.8, 2.1, 0.61, 0.56),
    Table1Row("Basketball", "Tissue", 0.004, 0.90, 0.56, 1.1, 1.8, 0.84, 0.83),
    Table1Row("Basketball", "Table tennis", 0.005, 0.90, 0.60, 1.2, 1.9, 0.84, 0.83),
)


def round_significant(x: float, digits: int = TABLE1_DIGITS) -> float:
    """Round ``x`` to ``digits`` significant figures (decimal, as printed).

    Parameters
    ----------
    x : float
        Value to round.
    digits : int, optional
        Significant figures, >= 1.

    Returns
    -------
    float
        The nearest float to the decimal rounding, so it compares equal to
        the printed literal (``round_significant(1.5158) == 1.5``).
    """
    if digits < 1:
        raise ParameterError("digits", "an integer >= 1", digits)
    return float(f"{float(x):.{digits}g}")


@dataclass(frozen=True)
class Table1Check:
    """Our ICM values for one row of Table 1 beside the printed ones.

    Attributes
    ----------
    index : int
        Row number in the table, from 1.
    row : Table1Row
        The printed row.
    v1, v2 : float
        Our ``v / |v0|`` from eq. (2.6), unrounded.
    v1_rounded, v2_rounded : float
        The same rounded to the printed two significant figures.
    v1_differs, v2_differs : bool
        Whether the rounded value differs from the printed ICM value.
    """

    index: int
    row: Table1Row
    v1: float
    v2: float
    v1_rounded: float
    v2_rounded: float
    v1_differs: bool
    v2_differs: bool

    @property
    def differs(self) -> bool:
        """True if either ICM column differs from the printed value."""
        return self.v1_differs or self.v2_differs

    @property
    def v1_difference(self) -> float:
        """Unrounded ours minus printed, upper ball."""
        return self.v1 - self.row.icm_v1

    @property
    def v2_difference(self) -> float:
        """Unrounded ours minus printed, lower ball."""
        return self.v2 - self.row.icm_v2


@checked(name="twoball.table1")
def table1_check(rows: tuple[Table1Row, ...] = TABLE1) -> tuple[Table1Check, ...]:
    """Recompute the ICM columns of Table 1 from mu, e2, e12 via eq. (2.6).

    The ratios are ``v / |v0|`` (see the module docstring for why not
    ``v / |u0|``), rounded to :data:`TABLE1_DIGITS` significant figures and
    compared with the printed values.  Nothing is fitted or adjusted.

    Findings: rows 1-3 (tennis ball below) agree with the printed values in
    both columns.  Row 4 (basketball / tennis) agrees in ``v1`` (2.1) but gives
    ``v2 = 0.488`` against the printed 0.56.  Rows 5 and 6 (basketball /
    tissue, basketball / table tennis) differ in both columns: 1.95 and 0.888
    against 1.8 and 0.83, and 2.02 and 0.885 against 1.9 and 0.83.

    Parameters
    ----------
    rows : tuple of Table1Row, optional
        Rows to check (one row alone is one); default the whole table.

    Returns
    -------
    tuple of Table1Check
        One entry per row, in order.

    Examples
    --------
    >>> import twoball
    >>> rows = twoball.table1()
    >>> [(c.row.upper, round(c.v1, 3), c.row.icm_v1) for c in rows[:3]]
    [('Coin', 1.516, 1.5), ('Nut', 1.493, 1.5), ('Table tennis', 1.771, 1.8)]
    """
    valid = "a tuple of Table1Row (rows of twoball.modal.icm.table1.TABLE1)"
    if isinstance(rows, Table1Row):
        rows = (rows,)
    try:
        rows = tuple(rows)
    except TypeError:  # not iterable
        raise ParameterError("rows", valid, rows) from None
    if not rows or not all(isinstance(row, Table1Row) for row in rows):
        raise ParameterError("rows", valid, rows)
    out = []
    for i, row in enumerate(rows, start=1):
        v1, v2 = touching_ratios(row.mu, row.e2, row.e12)
        r1 = round_significant(v1)
        r2 = round_significant(v2)
        out.append(
            Table1Check(
                index=i,
                row=row,
                v1=v1,
                v2=v2,
                v1_rounded=r1,
                v2_rounded=r2,
                v1_differs=r1 != row.icm_v1,
                v2_differs=r2 != row.icm_v2,
            )
        )
    return tuple(out)
