#pragma once
// What an oracle produces: a sequence of sampled orientations of a body on the
// ground plane z = 0, and for each the faces in contact.
#include <Eigen/Core>
#include <vector>

namespace rollcheck::oracle
{
struct Sample
{
  Eigen::Matrix3d rotation;          ///< body (relative to RollingBody::origin) to world
  Eigen::Vector3d angular_velocity;  ///< rad/s, world frame; zero when the oracle has none
  int support_vertex;                ///< lowest vertex at this orientation
  double ground_height_m;            ///< height subtracted before the threshold test (lowest centroid or vertex)
  int run;                           ///< rigid-body run the sample belongs to (0 for the approximate oracle)
};

struct Trajectory
{
  std::vector<Sample> samples;
  /// Contacts of sample s: contact_faces[contact_offsets[s] .. contact_offsets[s+1]).
  std::vector<int> contact_offsets{0};
  std::vector<int> contact_faces;
  bool has_angular_velocity = false;
  double contact_threshold_m = 0;
  long integration_steps = 0;        ///< rigid-body steps over all runs (0 for the approximate oracle)

  std::size_t size() const { return samples.size(); }
  const int* contacts_begin(std::size_t s) const { return contact_faces.data() + contact_offsets[s]; }
  const int* contacts_end(std::size_t s) const { return contact_faces.data() + contact_offsets[s + 1]; }
};
} // namespace rollcheck::oracle
