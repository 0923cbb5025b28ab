"""ellvor.plot with the Agg backend."""

import io

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection, LineCollection  # noqa: E402

import ellvor  # noqa: E402


def test_plot_draws_sites_edges_and_vertices(root):
    d = ellvor.build(root / "data" / "example-300.ell")
    fig, ax = plt.subplots()
    assert ellvor.plot(d, ax=ax, show_vertices=True, show_delaunay=True) is fig
    ellipses = [c for c in ax.collections if isinstance(c, EllipseCollection)]
    lines = [c for c in ax.collections if isinstance(c, LineCollection)]
    # Visible sites solid, the 30 hidden ones dashed.
    assert [len(c.get_offsets()) for c in ellipses] == [270, 30]
    assert ellipses[0].get_linestyle()[0][1] is None and ellipses[1].get_linestyle()[0][1] is not None
    # The Delaunay edges, then the Voronoi edges as one collection.
    assert [len(c.get_segments()) for c in lines] == [len(d.edges), len(d.trace())]
    assert len(ax.lines[0].get_xdata()) == len(d.faces)
    xmin, ymin, xmax, ymax = d.trace().box
    assert ax.get_xlim() == (xmin, xmax) and ax.get_ylim() == (ymin, ymax)
    png = io.BytesIO()
    fig.savefig(png, format="png")
    assert png.getvalue()[:8] == b"\x89PNG\r\n\x1a\n" and len(png.getvalue()) > 10_000
    plt.close(fig)


def test_plot_makes_its_own_figure():
    d = ellvor.build(ellvor.generate("circles", count=20, seed=2))
    fig = ellvor.plot(d, line_colors="r", show_sites=False)
    ax = fig.axes[0]
    assert [type(c) for c in ax.collections] == [LineCollection]
    plt.close(fig)
