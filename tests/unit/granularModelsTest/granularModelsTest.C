/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    granularModelsTest

Description
    GoogleTest unit tests of the models in src/: values against hand
    calculations, conservation and positivity of the segregation fluxes on
    a closed box, and the errors of bad input. Run in tests/unit/testCase
    (a 4x4x4 closed unit box) after blockMesh:
        granularModelsTest -case <copy of testCase>
    The tests are in one file per model family (<family>Tests.C); this
    file sets up the case they share (granularModelsTestFixtures.H).

\*---------------------------------------------------------------------------*/

#include "unitTestMain.H"

// ************************************************************************* //
