"""twoball.verify.output -- everything twoball writes: fields, files, pictures, figures, reports.

``fields`` (the solved ball and its nodal time series, the one builder
:func:`~twoball.verify.output.fields.ball_model`), ``series`` (XDMF, PVD and VTU
files, written and read back), ``render`` and ``palette`` (off-screen pictures
and animations), ``figures`` (matplotlib figures), ``report_files`` (report
directories) and ``options`` (:class:`~twoball.RenderOptions`,
:class:`~twoball.PlotOptions`).
"""

__all__ = ["fields", "options", "palette", "render", "report_files", "series", "figures"]
