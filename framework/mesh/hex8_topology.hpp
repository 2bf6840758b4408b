#pragma once
/// \file
/// Hex8 reference topology in the Exodus II convention (shared with Gmsh and VTK): nodes 0-3 on
/// the face ζ = -1, counter-clockwise seen from +ζ, and nodes 4-7 above them; faces numbered as
/// Exodus sides 1-6 (here 0-5), each listed counter-clockwise seen from outside the element.

namespace railfe {

/// Reference coordinates (ξ, η, ζ) of the eight hex8 nodes.
inline constexpr double kHex8NodeReference[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},
                                                    {-1, 1, -1},  {-1, -1, 1}, {1, -1, 1},
                                                    {1, 1, 1},    {-1, 1, 1}};

/// Element-local nodes of each face, ordered so their normal points out of the element.
inline constexpr int kHex8FaceNodes[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                             {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};

}  // namespace railfe
