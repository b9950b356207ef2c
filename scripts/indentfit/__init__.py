"""The inverse fit of indent's curves to measured ones (scripts/indent-fit.py, doc/inverse.md).

  params  the parameters to fit: their options, bounds and scaled coordinates
  misfit  measured and simulated curves as branches, and the residual vector between them
  runs    forward runs of indent, cached by their options and run concurrently
  stats   confidence intervals, correlations and the verdict on what the data can tell apart
"""
