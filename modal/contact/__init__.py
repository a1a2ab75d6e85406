"""A rigid upper body of finite mass in unilateral contact with the membrane.

One solver for every backend: :class:`~twoball.modal.contact.system.ContactSystem`
is built from any :class:`~twoball.modal.series.ModalSeries` and the modes' cap
averages; :func:`~twoball.modal.contact.events.integrate` runs the event-driven
scheme on the closed-form modal motion.  Dimensionless inside; SI in
:mod:`twoball.modal.contact.report`.
"""

__all__ = ["body", "caps", "events", "report", "states", "system", "trajectory"]
