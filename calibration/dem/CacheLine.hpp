#ifndef sdf_dem_CacheLine_hpp
#define sdf_dem_CacheLine_hpp

// Keeping the threads off each other's cache lines: a line written by two cores moves
// between them at every write (false sharing), which cost the streaming loops up to a
// third of their speed on two threads.

#include <cstddef>
#include <new>

namespace sdf::dem
{

constexpr std::size_t cacheLineBytes = 64;

//- Allocator of cache-line aligned storage: the threads' particle ranges start at
//  multiples of a line, so no cache line of a particle array is written by two threads.
template<class T>
struct CacheLineAllocator
{
    using value_type = T;
    static constexpr std::size_t alignment = cacheLineBytes;

    CacheLineAllocator() = default;
    template<class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}

    T* allocate(std::size_t n)
    {
        return static_cast<T*>(::operator new(n*sizeof(T), std::align_val_t(alignment)));
    }
    void deallocate(T* p, std::size_t) noexcept
    {
        ::operator delete(p, std::align_val_t(alignment));
    }
    template<class U>
    bool operator==(const CacheLineAllocator<U>&) const noexcept { return true; }
    template<class U>
    bool operator!=(const CacheLineAllocator<U>&) const noexcept { return false; }
};

//- A per-thread object (e.g. a vector a thread appends to) on cache lines of its own: the
//  threads' vector headers would otherwise share a line, and every push_back moves it.
template<class T>
struct alignas(cacheLineBytes) CacheLinePadded : T
{
    using T::T;
    CacheLinePadded() = default;
};

} // namespace sdf::dem

#endif
