#include "io/Checkpoint.hpp"
#include "io/Hdf5File.hpp"

#include <set>

namespace sdf::io
{

bool Checkpoint::operator==(const Checkpoint& other) const
{
    if (matrices.size() != other.matrices.size())
    {
        return false;
    }
    for (const auto& [name, matrix] : matrices)
    {
        const auto found = other.matrices.find(name);
        if (found == other.matrices.end()
         || found->second.rows() != matrix.rows()
         || found->second.cols() != matrix.cols()
         || found->second != matrix)
        {
            return false;
        }
    }
    return scalars == other.scalars && integers == other.integers
        && strings == other.strings && vectors == other.vectors
        && integerVectors == other.integerVectors;
}

namespace
{

template<class Map>
void collectNames(const Map& map, std::set<std::string>& names, const std::string& what, const std::string& path)
{
    for (const auto& entry : map)
    {
        if (!names.insert(entry.first).second)
        {
            throw Hdf5Error("checkpoint " + what + " name '" + entry.first + "' used twice", path, "");
        }
    }
}

} // namespace

void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint)
{
    std::set<std::string> attributeNames = {"kind"};
    collectNames(checkpoint.scalars, attributeNames, "scalar", path);
    collectNames(checkpoint.integers, attributeNames, "scalar", path);
    collectNames(checkpoint.strings, attributeNames, "scalar", path);
    std::set<std::string> arrayNames;
    collectNames(checkpoint.vectors, arrayNames, "array", path);
    collectNames(checkpoint.integerVectors, arrayNames, "array", path);
    collectNames(checkpoint.matrices, arrayNames, "array", path);

    AtomicFile out = AtomicFile::create(path);
    {
        const Group group = out.root().createGroup(checkpointGroup);
        group.setAttribute("kind", "periodicDEM checkpoint");
        for (const auto& [name, value] : checkpoint.scalars)
        {
            group.setAttribute(name, value);
        }
        for (const auto& [name, value] : checkpoint.integers)
        {
            group.setAttribute(name, value);
        }
        for (const auto& [name, value] : checkpoint.strings)
        {
            group.setAttribute(name, value);
        }
        for (const auto& [name, values] : checkpoint.vectors)
        {
            group.writeVector(name, values);
        }
        for (const auto& [name, values] : checkpoint.integerVectors)
        {
            group.writeInt64Vector(name, values);
        }
        for (const auto& [name, values] : checkpoint.matrices)
        {
            group.writeMatrix(name, values);
        }
    }
    out.commit();
}

Checkpoint readCheckpoint(const std::string& path)
{
    const File file = File::openReadOnly(path);
    const Group root = file.root();
    if (!root.hasGroup(checkpointGroup))
    {
        throw Hdf5Error("no checkpoint in this file", path, std::string("/") + checkpointGroup);
    }
    const Group group = root.openGroup(checkpointGroup);
    Checkpoint checkpoint;
    for (const std::string& name : group.attributeNames())
    {
        if (name == "kind")
        {
            continue;
        }
        switch (group.attributeType(name))
        {
            case AttributeType::floating:
                checkpoint.scalars[name] = group.readDouble(name);
                break;
            case AttributeType::integer:
                checkpoint.integers[name] = group.readInt64(name);
                break;
            default:
                checkpoint.strings[name] = group.readString(name);
                break;
        }
    }
    for (const std::string& name : group.childNames())
    {
        const std::size_t rank = group.openDataset(name).shape().size();
        if (rank == 2)
        {
            checkpoint.matrices[name] = group.readMatrix(name);
        }
        else if (group.isIntegerDataset(name))
        {
            checkpoint.integerVectors[name] = group.readInt64Vector(name);
        }
        else
        {
            checkpoint.vectors[name] = group.readVector(name);
        }
    }
    return checkpoint;
}

} // namespace sdf::io
