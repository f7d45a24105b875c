/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    breakageModelsTest

Description
    GoogleTest unit tests of the breakage models (selection rates, daughter
    distributions, fixed-pivot weights) on tests/unit/breakageCase: five
    classes of one material on an uneven grid and one of another material.

\*---------------------------------------------------------------------------*/

#include "unitTestMain.H"

// ************************************************************************* //
