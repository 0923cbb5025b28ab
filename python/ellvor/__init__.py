"""ellvor: the exact Voronoi diagram (Delaunay graph) of ellipses.

Every combinatorial answer is certified (floating-point filters, Arb balls,
exact algebra); exact values go in and out as ints and Fractions.

    import ellvor
    d = ellvor.build("data/example-300.ell")       # or a list of ellvor.Ellipse
    d.edges, d.faces, d.hidden                        # NumPy int64 arrays
    d.ridge_points, d.ridge_vertices                  # scipy.spatial.Voronoi's meaning
    ellvor.plot(d)                                    # matplotlib, like voronoi_plot_2d
    c = d.cells()                                     # certified cell areas: c.area_lo, c.area_hi

Numbers: an int, a Fraction (anything with numerator and denominator), a str
in the .ell grammar ("0.1" is exactly 1/10) or a float, taken exactly
(0.1 is 3602879701896397/2**55, as Fraction(0.1)).
"""

from ._errors import Error, InputError
from ._ellvor import PREDICATES, STAGES, Ellipse, Sites, read_sites, generate
from ._diagram import Ball, Diagram, Trace, VoronoiCircle, build
from ._cells import Cells
from ._predicates import Answer, incircle, side_of_bisector, voronoi_circle
from ._plot import plot

__all__ = [
    "PREDICATES", "STAGES", "Answer", "Ball", "Cells", "Diagram", "Ellipse", "Error", "InputError", "Sites", "Trace",
    "VoronoiCircle",
    "build", "generate", "incircle", "plot", "read_sites", "side_of_bisector", "voronoi_circle",
]
