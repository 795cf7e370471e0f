"""The front: the ``paramres`` command line, LaTeX report, figures and tables."""
