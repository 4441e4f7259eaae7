// A driver whose run fails on the last rank while the others wait in a collective: the
// situation of a solver error on one rank inside a distributed solve. driver_main must end
// the job (exit 1, the failing rank's one line) instead of leaving the others waiting for
// ever. Run by test_driver_rank_failure.sh under mpirun.
#include <stdexcept>

#include "io/driver_main.hpp"
#include "parallel/communicator.hpp"

int main(int argc, char** argv) {
  return rfmems::driver_main(
      "driver_rank_failure", "fails on the last rank while the others are in a reduction", {}, argc,
      argv,
      [](const rfmems::DriverOptions&) {
        const rfmems::Communicator world = rfmems::Communicator::world();
        if (world.rank() == world.size() - 1)
          throw std::runtime_error("injected failure on rank " + std::to_string(world.rank()));
        // The others wait in a reduction the failing rank never joins.
        return static_cast<int>(world.sum(rfmems::Real{1}));
      },
      rfmems::RankUse::AllRanks);
}
