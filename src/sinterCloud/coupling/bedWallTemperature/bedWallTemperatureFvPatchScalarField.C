// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "bedWallTemperatureFvPatchScalarField.H"
#include "keywordRange.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "basicThermo.H"
#include "contactMaterials.H"
#include "keywordSource.H"

namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        bedWallTemperatureFvPatchScalarField
    );
}


void Foam::bedWallTemperatureFvPatchScalarField::readData
(
    const dictionary& dict
)
{
    h_ = keywordRange::positive
    (
        dict, "h", "the bed-to-wall heat transfer coefficient [W/(m^2 K)]"
    );

    Text_ = keywordRange::above<scalar>
    (
        dict, "Text", 200, true,
        "the temperature outside the wall [K] (temperatures are in kelvin)"
    );

    // The particles' conductivity, from the case's one material file
    const contactMaterials materials
    (
        contactMaterials::read(patch().boundaryMesh().mesh())
    );
    const dictionary& material = materials.particleDict();
    if (!material.found("thermalConductivity"))
    {
        FatalIOErrorInFunction(material)
            << "No thermalConductivity in " << material.name()
            << ": the thermal wall condition (" << typeName << ") of "
            << dict.name() << " needs the particles' conductivity"
            << exit(FatalIOError);
    }
    ks_ = keywordRange::positive(material, "thermalConductivity", "[W/(m K)]");
}


Foam::bedWallTemperatureFvPatchScalarField::
bedWallTemperatureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(p, iF),
    h_(0),
    Text_(0),
    law_(dictionary()),
    ks_(0),
    voidageName_("voidage"),
    kineticName_("solidKineticConductivity"),
    kb_(p.size(), scalar(0))
{
    refValue() = Zero;
    refGrad() = Zero;
    valueFraction() = Zero;
}


Foam::bedWallTemperatureFvPatchScalarField::
bedWallTemperatureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    mixedFvPatchScalarField(p, iF),
    h_(0),
    Text_(0),
    law_(dict),
    ks_(0),
    voidageName_(dict.lookupOrDefault<word>("voidage", "voidage")),
    kineticName_
    (
        dict.lookupOrDefault<word>
        (
            "kineticConductivity",
            "solidKineticConductivity"
        )
    ),
    kb_(p.size(), scalar(0))
{
    readData(dict);

    fvPatchScalarField::operator=(scalarField("value", dict, p.size()));
    refValue() = Text_;
    refGrad() = Zero;
    if (dict.found("kb"))
    {
        kb_ = scalarField("kb", dict, p.size());
    }
    if (dict.found("valueFraction"))
    {
        valueFraction() = scalarField("valueFraction", dict, p.size());
    }
    else
    {
        valueFraction() = Zero;
    }
}


Foam::bedWallTemperatureFvPatchScalarField::
bedWallTemperatureFvPatchScalarField
(
    const bedWallTemperatureFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    mixedFvPatchScalarField(ptf, p, iF, mapper),
    h_(ptf.h_),
    Text_(ptf.Text_),
    law_(ptf.law_),
    ks_(ptf.ks_),
    voidageName_(ptf.voidageName_),
    kineticName_(ptf.kineticName_),
    kb_(ptf.kb_, mapper)
{}


Foam::bedWallTemperatureFvPatchScalarField::
bedWallTemperatureFvPatchScalarField
(
    const bedWallTemperatureFvPatchScalarField& ptf
)
:
    mixedFvPatchScalarField(ptf),
    h_(ptf.h_),
    Text_(ptf.Text_),
    law_(ptf.law_),
    ks_(ptf.ks_),
    voidageName_(ptf.voidageName_),
    kineticName_(ptf.kineticName_),
    kb_(ptf.kb_)
{}


Foam::bedWallTemperatureFvPatchScalarField::
bedWallTemperatureFvPatchScalarField
(
    const bedWallTemperatureFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(ptf, iF),
    h_(ptf.h_),
    Text_(ptf.Text_),
    law_(ptf.law_),
    ks_(ptf.ks_),
    voidageName_(ptf.voidageName_),
    kineticName_(ptf.kineticName_),
    kb_(ptf.kb_)
{}


void Foam::bedWallTemperatureFvPatchScalarField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    mixedFvPatchScalarField::autoMap(m);
    kb_.autoMap(m);
}


void Foam::bedWallTemperatureFvPatchScalarField::rmap
(
    const fvPatchScalarField& ptf,
    const labelList& addr
)
{
    mixedFvPatchScalarField::rmap(ptf, addr);
    const bedWallTemperatureFvPatchScalarField& tiptf =
        refCast<const bedWallTemperatureFvPatchScalarField>(ptf);
    kb_.rmap(tiptf.kb_, addr);
}


void Foam::bedWallTemperatureFvPatchScalarField::updateBedConductivity()
{
    const objectRegistry& db = this->db();
    if
    (
        !db.foundObject<volScalarField>(voidageName_)
     || !db.foundObject<volScalarField>(kineticName_)
     || !db.foundObject<basicThermo>(basicThermo::dictName)
    )
    {
        return;
    }

    const label patchi = patch().index();
    const scalarField eps
    (
        db.lookupObject<volScalarField>(voidageName_)
            .boundaryField()[patchi].patchInternalField()
    );
    const scalarField kKinetic
    (
        db.lookupObject<volScalarField>(kineticName_)
            .boundaryField()[patchi].patchInternalField()
    );
    const scalarField kf
    (
        db.lookupObject<basicThermo>(basicThermo::dictName).kappa(patchi)
    );

    forAll(kb_, facei)
    {
        kb_[facei] = law_.bed(eps[facei], kf[facei], ks_, kKinetic[facei]);
    }

    valueFraction() = h_/(h_ + kb_*patch().deltaCoeffs());
}


void Foam::bedWallTemperatureFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    updateBedConductivity();
    refValue() = Text_;
    refGrad() = Zero;

    mixedFvPatchScalarField::updateCoeffs();
}


void Foam::bedWallTemperatureFvPatchScalarField::setWallDiffusivity
(
    volScalarField& alphaEff,
    const basicThermo& thermo
)
{
    const volScalarField& T = thermo.T();
    volScalarField::Boundary& alphaBf = alphaEff.boundaryFieldRef();
    forAll(T.boundaryField(), patchi)
    {
        const fvPatchScalarField& Tp = T.boundaryField()[patchi];
        if (!isA<bedWallTemperatureFvPatchScalarField>(Tp))
        {
            continue;
        }
        bedWallTemperatureFvPatchScalarField& bc =
            const_cast<bedWallTemperatureFvPatchScalarField&>
            (
                refCast<const bedWallTemperatureFvPatchScalarField>(Tp)
            );
        bc.updateBedConductivity();

        alphaBf[patchi] =
            bc.kb()/thermo.Cp(thermo.p().boundaryField()[patchi], Tp, patchi);
    }
}


void Foam::bedWallTemperatureFvPatchScalarField::write(Ostream& os) const
{
    fvPatchScalarField::write(os);
    os.writeEntry("h", h_);
    os.writeEntry("Text", Text_);
    law_.write(os);
    os.writeEntryIfDifferent<word>("voidage", "voidage", voidageName_);
    os.writeEntryIfDifferent<word>
    (
        "kineticConductivity",
        "solidKineticConductivity",
        kineticName_
    );
    kb_.writeEntry("kb", os);
    refValue().writeEntry("refValue", os);
    refGrad().writeEntry("refGradient", os);
    valueFraction().writeEntry("valueFraction", os);
    writeEntry("value", os);
}
