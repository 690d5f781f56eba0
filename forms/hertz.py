# UFL forms for rollcheck's Hertz verification: a linear elastic body pressed
# onto the rigid plane z = 0, frictionless contact enforced by a penalty.
#
# Models (tag): "axi" axisymmetric (r, z) on triangles, "plane" plane strain
# (x, z) on triangles, "solid" 3D (x, y, z) on tetrahedra. Degrees 1 and 2.
# Every form name ends in _<tag>_p<degree>, so does every coefficient and
# constant it uses (u_axi_p1, youngs_modulus_axi_p1, ...): the C++ side
# (src/fem/contact_forms.cpp) looks them up by that suffix.
#
# Strain and stress are always the full 3x3 tensors in the order (x|r, y|theta,
# z): the 2D models add the out-of-plane strain (u_r / r axisymmetric, 0 plane
# strain), so one stress recovery serves all models.
#
# Frictionless penalty contact (P. Wriggers, Computational Contact Mechanics,
# 2nd ed., Springer 2006): with the gap
# g = z + u_z to the plane, the contact pressure is p = kappa <-g>_+ and the
# contact energy (kappa / 2) <-g>_+^2 on the candidate surface ds(1).
# kappa = c E / h is set by the caller (Pa/m), times a cellwise factor
# (penalty_scale, DG0, 1 unless the caller grades it with the mesh: a node
# penalty much softer than its small elements cuts a singular pressure off at
# h / c of the largest elements instead of the local ones). The gap may also
# carry an initial part (initial_gap, P1, 0 unless set): the height of a
# surface that the mesh represents flattened onto z = 0 (half-space theory's
# profile, K. L. Johnson, "Contact Mechanics", 1985, sec. 4.2).
#
# Integrals carry the weight w = 2 pi r for the axisymmetric model, so that
# forces and energies are those of the whole body of revolution; the plane
# strain model is per unit length, the 3D model per modelled part (the caller
# multiplies by the symmetry multiplicity).
import math

import numpy

from ufl import (Coefficient, Constant, FiniteElement, Form, SpatialCoordinate, TensorElement,
                 TestFunction, TrialFunction, VectorElement, as_tensor,
                 conditional, derivative, ds, dx, grad, inner, lt, tetrahedron,
                 triangle)

CONTACT_SURFACE = 1  # facet tag of the curved surface that may touch the plane


def contact_quadrature(tag, degree):
    """Quadrature of the contact integrals. 3D P1: the vertex rule, i.e. a
    node-based penalty with lumped nodal areas; it gives the same a and p0 as
    Gauss points and fewer active-set changes, so fewer Newton iterations
    (10 against 14 at the default mesh). Elsewhere Gauss points of degree 4
    (3 per interval, 6 per triangle): the axisymmetric weight r would leave
    the node on the axis without contact area under a vertex rule, and P2
    facets have no positive nodal rule."""
    if tag == "solid" and degree == 1:
        return {"quadrature_rule": "custom", "quadrature_degree": 1,
                "quadrature_points": numpy.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]),
                "quadrature_weights": numpy.array([1.0, 1.0, 1.0]) / 6}
    return {"quadrature_degree": 4}


cells = {"axi": triangle, "plane": triangle, "solid": tetrahedron}


def strain3(tag, u, x):
    """Full 3x3 small strain in (x|r, y|theta, z) order."""
    if tag == "solid":
        return 0.5 * (grad(u) + grad(u).T)
    g = grad(u)  # rows (u_x|u_r, u_z), columns (d/dx|d/dr, d/dz)
    shear = 0.5 * (g[0, 1] + g[1, 0])
    out_of_plane = u[0] / x[0] if tag == "axi" else 0.0
    return as_tensor([[g[0, 0], 0.0, shear],
                      [0.0, out_of_plane, 0.0],
                      [shear, 0.0, g[1, 1]]])


def stress3(eps, E, nu):
    """Isotropic Hooke's law, sigma = lambda tr(eps) I + 2 mu eps."""
    lmbda = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    trace = eps[0, 0] + eps[1, 1] + eps[2, 2]
    return as_tensor([[lmbda * trace * (i == j) + 2 * mu * eps[i, j]
                       for j in range(3)] for i in range(3)])


def lumped_mass_forms(tag):
    """Row sums of the P1 mass matrices, volume and contact surface, used by the
    nodal (lumped L2) recovery of stress and contact pressure; and the contact
    surface's consistent P1 mass matrix, for the consistent recovery of the
    pressure (src/fem/consistent_pressure.h), integrated exactly (degree 2, 3
    with the axisymmetric weight: Gauss degree 4)."""
    cell = cells[tag]
    x = SpatialCoordinate(cell)
    weight = 2 * math.pi * x[0] if tag == "axi" else 1.0
    element = FiniteElement("Lagrange", cell, 1)
    q = TestFunction(element)
    ds_exact = ds(CONTACT_SURFACE, metadata={"quadrature_degree": 4})
    return {f"volume_mass_{tag}": q * weight * dx,
            f"contact_mass_matrix_{tag}": TrialFunction(element) * q * weight * ds_exact}


def contact_forms(tag, degree):
    """Residual, Jacobian, energy and the contact and stress post-processing
    forms of one model and degree; names get the suffix _<tag>_p<degree>."""
    cell = cells[tag]
    x = SpatialCoordinate(cell)
    weight = 2 * math.pi * x[0] if tag == "axi" else 1.0
    z = len(x) - 1  # index of the vertical coordinate
    ds_contact = ds(CONTACT_SURFACE, metadata=contact_quadrature(tag, degree))

    element = VectorElement("Lagrange", cell, degree)
    u = Coefficient(element)
    v = TestFunction(element)
    du = TrialFunction(element)
    q = TestFunction(FiniteElement("Lagrange", cell, 1))
    tau = TestFunction(TensorElement("Lagrange", cell, 1, shape=(3, 3)))
    E = Constant(cell)
    nu = Constant(cell)
    kappa = Constant(cell)
    penalty_scale = Coefficient(FiniteElement("DG", cell, 0))
    initial_gap = Coefficient(FiniteElement("Lagrange", cell, 1))

    sigma = stress3(strain3(tag, u, x), E, nu)
    gap = x[z] + u[z] + initial_gap
    penetration = conditional(lt(gap, 0), -gap, 0)
    pressure = kappa * penalty_scale * penetration
    residual = (inner(sigma, strain3(tag, v, x)) * weight * dx
                - pressure * v[z] * weight * ds_contact)
    named = {
        "u": u, "youngs_modulus": E, "poisson_ratio": nu, "penalty_stiffness": kappa,
        "penalty_scale": penalty_scale, "initial_gap": initial_gap,
        "residual": residual,
        "jacobian": derivative(residual, u, du),
        "energy": (0.5 * inner(sigma, strain3(tag, u, x)) * weight * dx
                   + 0.5 * kappa * penalty_scale * penetration**2 * weight * ds_contact),
        "contact_force": pressure * weight * ds_contact,
        "pressure_load": pressure * q * weight * ds_contact,
        "contact_mass": q * weight * ds_contact,
        "stress_load": inner(sigma, tau) * weight * dx,
    }
    return {f"{name}_{tag}_p{degree}": value for name, value in named.items()}


for tag in cells:
    globals().update(lumped_mass_forms(tag))
    for degree in (1, 2):
        globals().update(contact_forms(tag, degree))

forms = [value for value in list(globals().values()) if isinstance(value, Form)]
