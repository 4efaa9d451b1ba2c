"""CLI subcommands, one module each (``add_arguments(parser)`` and ``run(args) -> int``).

They are registered in :data:`floatmoor.cli.COMMANDS`.  Heavy modules are imported inside
``run`` so that ``floatmoor --help`` stays fast.
"""
