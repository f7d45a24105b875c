#include "store/ProcessorStores.hpp"
#include "store/Store.hpp"

#include "io/Hdf5File.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <set>

namespace sdf::store
{

namespace
{

namespace fs = std::filesystem;

bool endsWith(const std::string& s, const std::string& tail)
{
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

//- Copies the attributes of one group or dataset; doubles and integers exactly.
void copyAttributes(const io::Node& from, const io::Node& to)
{
    for (const std::string& name : from.attributeNames())
    {
        switch (from.attributeType(name))
        {
            case io::AttributeType::floating:
                to.setAttribute(name, from.readDouble(name));
                break;
            case io::AttributeType::integer:
                to.setAttribute(name, from.readInt64(name));
                break;
            case io::AttributeType::string:
                to.setAttribute(name, from.readString(name));
                break;
            default:
                throw std::runtime_error
                (
                    "attribute " + from.path() + "/" + name
                  + " is of a type a calibration store does not hold"
                );
        }
    }
}

//- Copies one dataset of a condition group: vectors of doubles or integers (the
//  collision statistics' bin edges and histograms), matrices of doubles; exactly.
void copyDataset(const io::Group& from, const io::Group& to, const std::string& name)
{
    const std::vector<std::size_t> shape = from.openDataset(name).shape();
    const bool integer = from.isIntegerDataset(name);
    std::optional<io::Dataset> copy;
    if (shape.size() == 1 && integer)
    {
        copy = to.writeInt64Vector(name, from.readInt64Vector(name));
    }
    else if (shape.size() == 1)
    {
        copy = to.writeVector(name, from.readVector(name));
    }
    else if (shape.size() == 2 && !integer)
    {
        copy = to.writeMatrix(name, from.readMatrix(name));
    }
    else
    {
        throw std::runtime_error
        (
            from.path() + "/" + name + " is a dataset of a shape or type a calibration"
            " store does not hold"
        );
    }
    copyAttributes(from.openDataset(name), *copy);
}

//- Copies the attributes, datasets and sub-groups of one condition group, so a
//  merged condition equals the one its rank stored.
void copyGroup(const io::Group& from, const io::Group& to)
{
    copyAttributes(from, to);
    for (const std::string& child : from.childNames())
    {
        if (from.hasGroup(child))
        {
            copyGroup(from.openGroup(child), to.createGroup(child));
        }
        else
        {
            copyDataset(from, to, child);
        }
    }
}

} // namespace


std::string processorStorePath(const std::string& mainPath, int rank)
{
    const fs::path dir = fs::path(mainPath).parent_path();
    return (dir / ("calibration.processor" + std::to_string(rank) + ".h5")).string();
}


MergeSummary mergeProcessorStores(const std::string& mainPath)
{
    MergeSummary summary;
    fs::path dir = fs::path(mainPath).parent_path();
    if (dir.empty())
    {
        dir = ".";
    }
    if (!fs::is_directory(dir))
    {
        return summary;
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    {
        const std::string name = entry.path().filename().string();
        if (!entry.is_regular_file() || name.rfind("calibration.processor", 0) != 0)
        {
            continue;
        }
        if (endsWith(name, ".h5"))
        {
            summary.stores.push_back(entry.path().string());
        }
        else if (endsWith(name, ".h5.tmp"))
        {
            // A rank killed while adding a condition: the copy it was writing
            // is incomplete, its store holds every finished one.
            fs::remove(entry.path());
        }
    }
    std::sort(summary.stores.begin(), summary.stores.end());
    if (summary.stores.empty())
    {
        return summary;
    }

    const std::map<std::string, std::string> inMain = storedSettingsKeys(mainPath);
    std::string current = mainPath;
    try
    {
        std::optional<io::AtomicFile> out;
        std::set<std::string> copied;
        for (const std::string& store : summary.stores)
        {
            // The same checks as for the main store: a foreign or corrupt
            // file stops the merge with the file named, untouched
            current = store;
            storedSettingsKeys(store);
            const io::File in = io::File::openReadOnly(store);
            const io::Group root = in.root();
            if (!root.hasGroup("conditions"))
            {
                continue;
            }
            const io::Group conditions = root.openGroup("conditions");
            for (const std::string& name : conditions.childNames())
            {
                if (inMain.count(name) || copied.count(name))
                {
                    continue;
                }
                if (!out)
                {
                    current = mainPath;
                    const bool exists = fs::is_regular_file(mainPath);
                    out.emplace(exists ? io::AtomicFile::update(mainPath) : io::AtomicFile::create(mainPath));
                    if (!exists)
                    {
                        for (const char* attr : {"content", "fineSpecies", "coarseSpecies"})
                        {
                            out->root().setAttribute(attr, root.readString(attr));
                        }
                    }
                    current = store;
                }
                copyGroup(conditions.openGroup(name), out->root().createGroup("conditions/" + name));
                copied.insert(name);
                ++summary.conditionsMoved;
            }
        }
        if (out)
        {
            current = mainPath;
            out->commit();
        }
    }
    catch (const StoreError&)
    {
        throw;
    }
    catch (const std::exception& err)
    {
        throw StoreError(current, std::string("merging the processor stores failed: ") + err.what());
    }
    for (const std::string& store : summary.stores)
    {
        fs::remove(store);
        fs::remove(store + ".tmp");
    }
    return summary;
}

} // namespace sdf::store
