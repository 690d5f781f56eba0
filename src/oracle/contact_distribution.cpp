#include "oracle/contact_distribution.h"

namespace rollcheck::oracle
{
ContactDistribution contact_distribution(const Trajectory& trajectory, const Eigen::VectorXd& face_areas,
                                         long convergence_every)
{
  ContactDistribution out;
  out.counts = Eigen::VectorXd::Zero(face_areas.size());
  const ScoreTemplate score(face_areas);
  for (std::size_t s = 0; s < trajectory.size(); ++s)
  {
    for (const int* f = trajectory.contacts_begin(s); f != trajectory.contacts_end(s); ++f)
      out.counts[*f] += 1;
    const long done = static_cast<long>(s) + 1;
    if (convergence_every > 0 && done % convergence_every == 0)
      out.convergence.emplace_back(done, score(out.counts));
  }
  out.summary = summarize_distribution(out.counts, face_areas);
  return out;
}
} // namespace rollcheck::oracle
