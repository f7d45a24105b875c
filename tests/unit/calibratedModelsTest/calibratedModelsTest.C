/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    calibratedModelsTest

Description
    GoogleTest unit tests of the calibrated models (src/calibratedModels,
    libcalibratedModels): the fitted laws and their envelope, the tabulated
    calibration read from a synthetic calibration.h5, runDEM extending it.
    Run in tests/unit/testCase (a 4x4x4 closed unit box) after blockMesh:
        calibratedModelsTest -case <copy of testCase>
    The tests are in calibratedModelsTests.C; this file sets up the case,
    as granularModelsTest does (granularModelsTestFixtures.H).

\*---------------------------------------------------------------------------*/

#include "unitTestMain.H"

// ************************************************************************* //
