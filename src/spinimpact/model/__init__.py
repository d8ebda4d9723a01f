"""The user-facing object layer: bodies, restitution models, :func:`solve`.

It validates input, calls :mod:`spinimpact.core` and packages the results; it
never re-implements physics.
"""
