/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibrationStore.H"
#include "error.H"
#include "messageStream.H"

#include "store/Store.hpp"
#include "store/ProcessorStores.hpp"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

std::map<std::string, std::string>
Foam::calibrationStore::storedConditions(const fileName& h5)
{
    try
    {
        return sdf::store::storedSettingsKeys(h5);
    }
    catch (const sdf::store::StoreError& err)
    {
        FatalErrorInFunction
            << "Cannot use " << h5 << " as the calibration store:" << nl
            << "    " << err.message().c_str() << nl
            << "    The file is left untouched: move it away (or remove it)"
            << " to start a new calibration." << nl << exit(FatalError);
    }
    return {};
}


bool Foam::calibrationStore::isStored
(
    const fileName& h5,
    const std::map<std::string, std::string>& stored,
    const std::string& name,
    const std::string& key
)
{
    try
    {
        return sdf::store::isStored(h5, stored, name, key);
    }
    catch (const sdf::store::SettingsMismatch& err)
    {
        const std::string added = err.addedSinceStored();
        if (!added.empty())
        {
            FatalErrorInFunction
                << "Condition " << name.c_str() << " in " << h5
                << " was written before the measurement changed (the"
                << " settings are the same; the current key adds \""
                << added.c_str() << "\"):" << nl
                << "    stored:  " << err.storedKey().c_str() << nl
                << "    current: " << err.currentKey().c_str() << nl
                << "    Move the file away to rerun its conditions."
                << nl << exit(FatalError);
        }
        FatalErrorInFunction
            << "Condition " << name.c_str() << " in " << h5
            << " was run with other DEM settings:" << nl
            << "    stored:  " << err.storedKey().c_str() << nl
            << "    current: " << err.currentKey().c_str() << nl
            << "    Move the file away to recalibrate, or restore"
            << " the settings." << nl << exit(FatalError);
    }
    return false;
}


Foam::label Foam::calibrationStore::mergeProcessorStores(const fileName& h5)
{
    sdf::store::MergeSummary summary;
    try
    {
        summary = sdf::store::mergeProcessorStores(h5);
    }
    catch (const sdf::store::StoreError& err)
    {
        FatalErrorInFunction
            << "Merging the processor stores beside " << h5 << " into it"
            << " failed:" << nl << "    " << err.what() << nl
            << "    The processor stores are left as they are." << nl
            << exit(FatalError);
    }
    if (summary.stores.empty())
    {
        return 0;
    }
    Info<< "Merged " << label(summary.conditionsMoved) << " conditions of "
        << label(summary.stores.size()) << " processor stores into " << h5
        << nl << endl;
    return label(summary.conditionsMoved);
}


// ************************************************************************* //
