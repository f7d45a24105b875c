// The stores of the MPI ranks of a parallel calibration: each rank appends
// its conditions to calibration.processor<N>.h5 beside the main store (serial
// HDF5, one writer per file); the master merges them into the main store at
// the end of a run and at the start of any run, so that nothing a killed
// parallel run finished is lost.
#ifndef sdf_store_ProcessorStores_hpp
#define sdf_store_ProcessorStores_hpp

#include <cstddef>
#include <string>
#include <vector>

namespace sdf::store
{

//- The store of rank `rank` beside the main store mainPath:
//  <dir>/calibration.processor<rank>.h5
std::string processorStorePath(const std::string& mainPath, int rank);

struct MergeSummary
{
    std::vector<std::string> stores;   // the processor stores found, sorted
    std::size_t conditionsMoved = 0;
};

//- Moves the conditions of every processor store in the directory of
//  mainPath into the main store, in one atomic update, then removes the
//  processor stores. A condition already in the main store is not copied
//  again (a merge killed between the update of the main store and the
//  removal of the processor stores is completed by the next run). Removes
//  the temporary copies (<store>.h5.tmp) a killed rank left. Call when no
//  rank writes. Throws StoreError naming the file if a store is not ours or
//  the merge fails; the processor stores are then left as they are.
MergeSummary mergeProcessorStores(const std::string& mainPath);

} // namespace sdf::store

#endif
