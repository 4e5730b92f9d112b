// Bolt steel calibrated to the mesh: the seed's bilinear law (eqs. 4-7:
// Eb, sigma_y, sigma_u, ET; brittle shear tau_y) turned into the elasticity
// of the bolt strip's triangles plus the bolt-steel crack law (eqs. 11-19)
// of the crack elements inside the strip, scaled for the row spacing
// (eq. 20). In the model the bolt is the strip of marked triangles, width w
// (its area over the bolt length), one metre deep. The strip's stresses and
// strengths are the steel's times
//   f = (d / w) / s_b
// (d / w = 1 when the strip is the bolt's own width; eq. 20's 1 / s_b for
// row spacing s_b), so the strip carries the force per metre of tunnel of
// one bolt of width d every s_b metres. Strains are not scaled.
//
// Calibration (why the triangles are stiffer than Eb). The crack elements
// add compliance: below yield each opens along its pre-peak curve up to op =
// 2 h sigma_y / pn, which would add strain 2 h sigma_y / (pn spacing) and
// spoil the yield strain. With the crack-compliance sum of a strip in
// uniaxial stress along t,
//   extra strain = (1/A) sum_c h_c [o_c (n.t)^2 + |s_c| |n.t||e.t|],
// evaluated at sigma_y on each crack's pre-peak curve, (n, e the crack's
// normal and tangent), the triangles get the uniaxial modulus
//   E_tri = Eb (1 + g / k),  g = extra strain * pn / sigma_y,  pn = k E_tri,
// so the secant at yield is exactly Eb. Beyond yield the cracks across the
// axis open from op to or, sigma = sigma_y + D (sigma_u - sigma_y), so the
// hardening compliance 1/ET = 1/E_tri + q (or - op) / (sigma_u - sigma_y),
// q = (1/A) sum over cracks within 45 deg of across of h_c (n.t)^2; this
// fixes or - op and, by eq. 14, GfI = (sigma_y + sigma_u)(or - op) / 2. The
// strip breaks when D = 1, at eps_u = eps_y + (sigma_u - sigma_y) / ET.
// Exact for a strip of cells whose crack elements are across the axis or
// nearly along it (tested); an unstructured strip gets the same sums, with
// inclined cracks only approximated in the hardening part.
#pragma once

#include <array>
#include <vector>

#include "rockfdem/fdem/bolt_marking.hpp"
#include "rockfdem/fdem/model_input.hpp"

namespace rockfdem::fdem {

/// The seed's steel (Table 5 style). Strengths are the steel's own, unscaled.
struct BoltSteel {
  double young = 200e9;                 ///< Eb [Pa]
  double yield_strength = 400e6;        ///< sigma_y [Pa]
  double ultimate_strength = 500e6;     ///< sigma_u [Pa]
  double tangent_modulus = 2e9;         ///< ET [Pa]: eps_u = eps_y + (sigma_u - sigma_y) / ET
  double shear_yield_strength = 240e6;  ///< tau_y = tau_u [Pa] (brittle)
  double gf_II = 1e4;          ///< shear fracture energy [J/m^2] (sr - sp = 3 GfII / tau_y)
  double penalty_factor = 10;  ///< crack penalties pn = pt = factor * E_tri
};

/// One crack element inside a bolt strip, for the calibration.
struct StripCrack {
  double length = 0;  ///< h_c [m]
  double cos_n = 0;   ///< |n . t|: 1 for a crack across the axis
  double cos_e = 0;   ///< |e . t|: 1 for a crack along the axis
};

/// The strip of one bolt as the calibration needs it.
struct BoltStrip {
  double area = 0;                 ///< sum of the strip's triangle areas [m^2]
  double length = 0;               ///< bolt length [m]
  double width = 0;                ///< area / length [m]
  std::vector<StripCrack> cracks;  ///< edges shared by two triangles of the strip
};

/// The strip of bolt b from the mesh (triangles of `marks` owned by b).
BoltStrip bolt_strip(const ModelInput& in, const BoltMarks& marks, int b, const Bolt& bolt);

/// Scale f = (d / w) / s_b of the strip's stresses (see the header comment).
double bolt_scale(const Bolt& bolt, const BoltStrip& strip, double row_spacing);

/// The steel as the model needs it.
struct BoltSteelModel {
  Material crack;                 ///< bolt-steel crack material (law kBoltSteel), scaled by f
  double triangle_modulus = 0;    ///< uniaxial modulus of the strip's triangles, f E_tri [Pa]
  double scale = 1;               ///< f
  double yield_flexibility = 0;   ///< g
  double transverse_density = 0;  ///< q [1/m]
};

/// Calibrates the steel to the strip (header comment). Throws InputError
/// when the strip has no crack element across its axis (it could not yield)
/// or a crack whose shear would reach tau_y before the axis yields.
BoltSteelModel bolt_steel_model(const BoltSteel& steel, double row_spacing, const Bolt& bolt,
                                const BoltStrip& strip);

/// Eq. 20 alone: the seed's steel Material (law kBoltSteel) with stiffness
/// and strengths multiplied by 1 / s_b and no mesh calibration (GfI from
/// the ultimate strain over `crack_spacing`, the mean distance between
/// cracks across the bolt).
Material row_spacing_scaled_steel(const BoltSteel& steel, double row_spacing, double crack_spacing);

}  // namespace rockfdem::fdem
