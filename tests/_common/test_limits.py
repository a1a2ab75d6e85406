"""The time limit's defaults (twoball._common.budget): off, per verb, following the estimates."""

from __future__ import annotations

import math
import time

import pytest

from twoball._common import budget
from twoball._common.budget import (
    DEFAULT_MAX_SECONDS,
    ESTIMATE_SLACK,
    Budget,
    DeadlineError,
    Estimate,
    MiB,
    check,
    check_deadline,
    limits,
    running,
    verb_default,
)


def _started_ago(seconds: float) -> None:
    """Put the running clock's start ``seconds`` in the past (and re-read the limit)."""
    budget._clock.update(start=time.monotonic() - seconds, read=None)


def test_off_is_no_limit() -> None:
    assert budget.parse_seconds("off") == math.inf == budget.parse_seconds(" None ")
    assert budget.format_seconds(math.inf) == "off"
    assert Budget.from_options(None, "off").max_seconds == math.inf
    with pytest.raises(budget.ParameterError, match="or off"):
        budget.parse_seconds("soon")


def test_the_default_follows_and_a_given_limit_does_not(monkeypatch) -> None:
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    assert Budget.from_options(None, None).follows
    assert not Budget.from_options(None, "5min").follows
    monkeypatch.setenv(budget.TIME_ENV, "5min")
    assert not Budget.from_options(None, None).follows  # the environment gives one too


def test_the_default_deadline_follows_an_accepted_estimate(monkeypatch) -> None:
    """Left at the default, a run the estimates accepted (4 min) is not stopped at 5 min
    (a loaded machine), only past ESTIMATE_SLACK times its estimate."""
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    with limits(), running():
        check("work", Estimate(MiB, 240.0))
        _started_ago(DEFAULT_MAX_SECONDS + 60)
        check_deadline("the work")  # 6 min: within 10 x 4 min
        _started_ago(ESTIMATE_SLACK * 240.0 + 5)
        with pytest.raises(DeadlineError, match="the default time limit 40 min"):
            check_deadline("the work")


def test_without_an_estimate_the_default_deadline_is_five_minutes(monkeypatch) -> None:
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    with limits(), running():
        _started_ago(DEFAULT_MAX_SECONDS - 5)
        check_deadline("the work")
        _started_ago(DEFAULT_MAX_SECONDS + 1)
        with pytest.raises(DeadlineError, match="the default time limit 5 min"):
            check_deadline("the work")


def test_a_given_limit_is_the_deadline_whatever_the_estimates() -> None:
    with limits(max_time="5min"), running():
        check("work", Estimate(MiB, 240.0))
        _started_ago(DEFAULT_MAX_SECONDS + 1)
        with pytest.raises(DeadlineError, match=r"at the time limit 5 min .*max_time\)"):
            check_deadline("the work")


def test_a_verb_without_a_default_deadline(monkeypatch) -> None:
    """reproduce: no default deadline (inf) and nothing refused for time; a limit given
    (the option or the environment) stands."""
    monkeypatch.delenv(budget.TIME_ENV, raising=False)
    with limits(), running(), verb_default(math.inf):
        check("work", Estimate(MiB, 86400.0))  # a day: not refused
        _started_ago(86400.0 * 20)
        check_deadline("the work")
    monkeypatch.setenv(budget.TIME_ENV, "20s")
    with limits(), running(), verb_default(math.inf):
        with pytest.raises(budget.BudgetError, match="limit 20 s"):
            check("work", Estimate(MiB, 60.0))
