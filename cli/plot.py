"""`sears-paradox plot`: placeholder until the drawing command lands (issue 3)."""

import click


@click.command()
def plot() -> None:
    """Draw Minkowski diagrams (not yet available).

    Example: sears-paradox plot fig2 --v 0.6
    """
    raise click.ClickException("plot is not implemented yet.")
