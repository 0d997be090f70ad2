"""Speed against accuracy: graphplan's methods and its peers, measured in the same run.

``python -m benchmarks`` (see :mod:`benchmarks.run` and ``docs/benchmarks.md``).
"""
