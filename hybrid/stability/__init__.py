"""The sampled loops' small-signal model, their stability and margins, maps of the stable region, and gains.

:mod:`~hybrid.stability.model` is the model (conventions §15), :mod:`~hybrid.stability.experiment_loops` reads
an experiment into it, :mod:`~hybrid.stability.analysis` judges it (:func:`stability`).
"""
