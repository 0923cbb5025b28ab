"""ellvor.plot: a diagram drawn with matplotlib, like scipy.spatial.voronoi_plot_2d."""

import numpy as np


def plot(diagram, ax=None, *, show_sites=True, show_vertices=False, show_delaunay=False, line_colors="k",
         line_width=1.0, line_alpha=1.0, point_size=None, site_color="tab:blue", tolerance=0.005, margin=0.08,
         cells=None, color="packing_fraction", cmap="viridis"):
    """Draws ``diagram`` on ``ax`` (a new figure's axes when None) and returns the Figure.

    Sites are ellipses (hidden ones dashed); the Voronoi edges, traced along the
    bisectors (``Diagram.trace(tolerance, margin)``), are one LineCollection; the
    view is the sites' bounding box plus ``margin``, with equal axes.
    ``show_vertices`` marks the Voronoi vertices, ``show_delaunay`` draws the
    Delaunay edges between the sites' centers. ``line_colors``, ``line_width``,
    ``line_alpha`` and ``point_size`` as in voronoi_plot_2d.
    ``cells`` (a Cells of this diagram, ``d.cells()``): fills each bounded cell's ring with its
    ``color`` (``"packing_fraction"``: the midpoint of its certified interval, for the eye) on
    ``cmap``, with a colour bar; where a cell has no ring, its site is filled with the cell's
    colour instead. Unbounded and hidden cells are left unfilled.
    """
    # matplotlib is imported here: `import ellvor` must not need it.
    import matplotlib.pyplot as plt
    from matplotlib.collections import EllipseCollection, LineCollection

    if ax is None:
        ax = plt.figure().gca()
    trace = diagram.trace(tolerance, margin)
    xmin, ymin, xmax, ymax = trace.box

    if cells is not None:
        _fill_cells(ax, diagram, cells, color, cmap)
    if show_sites and len(diagram):
        values = diagram.sites.to_array()  # a b w xc yc
        hidden = np.zeros(len(values), dtype=bool)
        hidden[diagram.hidden[:, 0]] = True
        for mask, style in ((~hidden, "solid"), (hidden, "dashed")):
            if not mask.any():
                continue
            a, b, w, xc, yc = values[mask].T
            # w = tan(omega / 2), omega the angle of the a-axis.
            ax.add_collection(EllipseCollection(2 * a, 2 * b, np.degrees(2 * np.arctan(w)), units="xy",
                                                offsets=np.column_stack([xc, yc]), offset_transform=ax.transData,
                                                facecolors="none", edgecolors=site_color, linewidths=0.8,
                                                linestyles=style))
    if show_delaunay and len(diagram.edges):
        ax.add_collection(LineCollection(diagram.points[diagram.edges], colors="0.75", linewidths=0.5))
    ax.add_collection(LineCollection(trace.polylines, colors=line_colors, linewidths=line_width,
                                     alpha=line_alpha))
    if show_vertices and len(diagram.faces):
        kw = {} if point_size is None else {"markersize": point_size}
        ax.plot(diagram.vertices[:, 0], diagram.vertices[:, 1], "o", color="tab:orange", **kw)
    ax.set_xlim(xmin, xmax)
    ax.set_ylim(ymin, ymax)
    ax.set_aspect("equal")
    return ax.figure


def _fill_cells(ax, diagram, cells, color, cmap):
    """The cells (or, without rings, the sites) filled by ``color``, with a colour bar."""
    from matplotlib.collections import EllipseCollection, PolyCollection

    if color != "packing_fraction":
        raise ValueError(f"color: expected 'packing_fraction', got {color!r}")
    if len(cells) != len(diagram):
        raise ValueError("cells: not the cells of this diagram (another number of sites)")
    value = (cells.packing_fraction_lo + cells.packing_fraction_hi) / 2
    shown = cells.visible & cells.bounded & np.isfinite(value)
    rings = cells.rings()
    have_rings = shown.any() and all(len(rings[k]) for k in np.flatnonzero(shown))
    if have_rings:
        ids = np.flatnonzero(shown)
        filled = PolyCollection([rings[k] for k in ids], array=value[ids], cmap=cmap, edgecolors="none")
        label = "local packing fraction (interval midpoint)"
    else:
        ids = np.flatnonzero(shown)
        a, b, w, xc, yc = diagram.sites.to_array()[ids].T
        filled = EllipseCollection(2 * a, 2 * b, np.degrees(2 * np.arctan(w)), units="xy",
                                   offsets=np.column_stack([xc, yc]), offset_transform=ax.transData,
                                   array=value[ids], cmap=cmap, edgecolors="none")
        label = "local packing fraction (interval midpoint; no rings yet: sites filled)"
    ax.add_collection(filled)
    ax.figure.colorbar(filled, ax=ax, label=label)
    return filled
