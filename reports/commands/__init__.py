"""One module per ``paramres`` sub-command; each defines ``register(subparsers)``."""
