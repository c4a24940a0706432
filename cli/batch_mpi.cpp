// simdphys-batch-mpi FILE: a batch file's jobs across MPI processes (and, within each, across its
// cores with OpenMP): rank r runs jobs r, r + size, r + 2 size, ...; rank 0 gathers the results,
// prints them in job order and writes the report. Every rank reads the batch file and the scenes
// itself, so on a cluster they must be on a shared file system (docs/batch.md).
#include <mpi.h>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  CLI::App app{"simdphys-batch-mpi: a batch file's jobs across MPI processes (docs/batch.md)"};
  std::string file, json;
  int threads = 0;
  app.add_option("file", file, "The batch file (JSON)")->required();
  app.add_option("--threads", threads, "Jobs at a time in each process, 0 for OpenMP's default");
  app.add_option("--json", json, "Rank 0 writes the results to this JSON file");
  int status = 0;
  try {
    app.parse(argc, argv);
    const std::vector<simdphys::BatchJob> all = simdphys::loadBatch(file);
    std::vector<simdphys::BatchJob> mine;
    std::vector<std::uint64_t> indices;
    for (std::size_t i = std::size_t(rank); i < all.size(); i += std::size_t(size))
      mine.push_back(all[i]), indices.push_back(i);
    const std::vector<simdphys::BatchResult> results = simdphys::runBatch(mine, threads, indices);
    // The results are flat records: gathered as bytes, placed by their job index.
    const int bytes = int(results.size() * sizeof(simdphys::BatchResult));
    std::vector<int> counts(static_cast<std::size_t>(size)), offsets(counts.size());
    MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    for (int r = 1; r < size; ++r)
      offsets[std::size_t(r)] = offsets[std::size_t(r - 1)] + counts[std::size_t(r - 1)];
    std::vector<simdphys::BatchResult> gathered(rank == 0 ? all.size() : 0);
    std::vector<simdphys::BatchResult> received(rank == 0 ? all.size() : 0);
    MPI_Gatherv(results.data(), bytes, MPI_BYTE, received.data(), counts.data(), offsets.data(),
                MPI_BYTE, 0, MPI_COMM_WORLD);
    if (rank == 0) {
      for (const simdphys::BatchResult& r : received) gathered[r.job] = r;
      std::printf("%zu jobs over %d processes\n", all.size(), size);
      simdphys::cli::printBatch(gathered);
      if (!json.empty()) simdphys::cli::writeReport(gathered, json);
    }
  } catch (const CLI::ParseError& e) {
    status = rank == 0 ? app.exit(e) : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error (rank %d): %s\n", rank, e.what());
    status = 1;
  }
  MPI_Finalize();
  return status;
}
