// A host-side reference for the pbr material's albedo table
// (kernels/bsdf_pbr_albedo.cl): the directional albedo of the specular lobe
// of the material's dielectric part, computed by quadrature, independently
// of the kernels. Used by the generator of the table and by its test.
#pragma once

namespace orb::render::test {

// Shape of the table: kPbrAlbedoSize x kPbrAlbedoSize nodes at
// cos(theta_o) = i / (size - 1) and roughness = j / (size - 1).
inline constexpr int kPbrAlbedoSize = 32;

// The fraction of the energy arriving from a direction at cos(theta_o) =
// cos_o that GGX microfacets of perceptual roughness `roughness` (alpha =
// roughness^2) with Schlick's Fresnel of reflectance f0 at normal incidence
// (0.04: the table's dielectric layer; 1: a white metal), and Smith's height-correlated
// masking-shadowing reflect, single scattering only:
//   E(cos_o) = integral of f_spec(wo, wi) cos(theta_i) over the hemisphere.
// Integrated over the visible normals of wo (Heitz 2018's parametrisation)
// with n x n midpoint samples. Alpha below 1e-3 is a smooth surface, whose
// albedo is Schlick's F(cos_o) (the kernels treat it as a delta lobe).
double pbr_specular_albedo(double cos_o, double roughness, int n, double f0 = 0.04);

// The same quadrature for rough glass (Walter et al. 2007, with GGX and
// height-correlated Smith masking): the share of the energy arriving from
// cos(theta_o) = cos_o on the side of index n_o that the interface to index
// n_i reflects or transmits, single scattering. roughness >= sqrt(1e-3).
double rough_dielectric_albedo(double cos_o, double roughness, double n_o, double n_i, int n);

}  // namespace orb::render::test
