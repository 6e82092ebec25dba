// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "superficialInletVelocityFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"


Foam::superficialInletVelocityFvPatchVectorField::
superficialInletVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(p, iF),
    superficialVelocity_(),
    alphaName_("voidage")
{}


Foam::superficialInletVelocityFvPatchVectorField::
superficialInletVelocityFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    fixedValueFvPatchVectorField(p, iF, dict),
    superficialVelocity_
    (
        Function1<vector>::New("superficialVelocity", dict)
    ),
    alphaName_(dict.lookupOrDefault<word>("alpha", "voidage"))
{}


Foam::superficialInletVelocityFvPatchVectorField::
superficialInletVelocityFvPatchVectorField
(
    const superficialInletVelocityFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    fixedValueFvPatchVectorField(ptf, p, iF, mapper),
    superficialVelocity_(ptf.superficialVelocity_.clone()),
    alphaName_(ptf.alphaName_)
{}


Foam::superficialInletVelocityFvPatchVectorField::
superficialInletVelocityFvPatchVectorField
(
    const superficialInletVelocityFvPatchVectorField& ptf
)
:
    fixedValueFvPatchVectorField(ptf),
    superficialVelocity_(ptf.superficialVelocity_.clone()),
    alphaName_(ptf.alphaName_)
{}


Foam::superficialInletVelocityFvPatchVectorField::
superficialInletVelocityFvPatchVectorField
(
    const superficialInletVelocityFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    fixedValueFvPatchVectorField(ptf, iF),
    superficialVelocity_(ptf.superficialVelocity_.clone()),
    alphaName_(ptf.alphaName_)
{}


void Foam::superficialInletVelocityFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    const scalar t = db().time().timeOutputValue();
    const fvPatchScalarField& alphap =
        patch().lookupPatchField<volScalarField, scalar>(alphaName_);

    const vector Us(superficialVelocity_->value(t));
    operator==(Us*(1/static_cast<const scalarField&>(alphap)));

    fixedValueFvPatchVectorField::updateCoeffs();
}


void Foam::superficialInletVelocityFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    superficialVelocity_->writeData(os);
    os.writeEntryIfDifferent<word>("alpha", "voidage", alphaName_);
    writeEntry("value", os);
}


namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        superficialInletVelocityFvPatchVectorField
    );
}
