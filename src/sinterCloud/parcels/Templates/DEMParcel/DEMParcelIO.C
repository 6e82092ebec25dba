// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMParcel.H"
#include "IOstreams.H"
#include "IOField.H"
#include "PtrList.H"

template<class ParcelType>
Foam::string Foam::DEMParcel<ParcelType>::propertyList_ =
    Foam::DEMParcel<ParcelType>::propertyList();


template<class ParcelType>
Foam::DEMParcel<ParcelType>::DEMParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    displacement_(Zero),
    demIndex_(-1)
{
    if (readFields)
    {
        // The rest of the step's displacement, a flag, then the state (a
        // parcel in transit carries them)
        label hasState;
        is >> displacement_ >> hasState;
        if (hasState)
        {
            state_.reset(new demParcelState());
            is >> state_();
        }
    }

    is.check(FUNCTION_NAME);
}


namespace Foam
{
namespace DEMParcelDetail
{

//- A lagrangian field-field of the cloud if its file is there (on any
//  processor). Written in binary its class is the compact one
//  (scalarFieldCompactField), in ASCII the plain one (scalarFieldField);
//  FieldType (a CompactIOField) reads either
template<class FieldType, class CloudType>
bool present(const CloudType& c, const word& name)
{
    IOobject io(c.fieldIOobject(name, IOobject::MUST_READ));
    const bool found =
        io.template typeHeaderOk<FieldType>(false)
     && (
            io.headerClassName() == FieldType::typeName
         || io.headerClassName()
         == IOField<typename FieldType::value_type>::typeName
        );
    return returnReduce(found, orOp<bool>());
}


//- Read the lagrangian field-field name into fields[i] if its file is there
template<class FieldType, class CloudType>
void readIfPresent
(
    CloudType& c,
    const word& name,
    const bool valid,
    PtrList<FieldType>& fields,
    const label i
)
{
    if (present<FieldType>(c, name))
    {
        fields.set
        (
            i,
            new FieldType(c.fieldIOobject(name, IOobject::MUST_READ), valid)
        );
        c.checkFieldFieldIOobject(c, fields[i]);
    }
}


//- The cloud's contact slots (DEMCloud); other layers cannot say
template<class CloudType>
inline auto slotsOf(const CloudType& c, int) -> decltype(c.contactSlotLayout())
{
    return c.contactSlotLayout();
}

template<class CloudType>
inline const contactSlots& slotsOf(const CloudType& c, long)
{
    FatalErrorInFunction
        << "The DEM parcel's fields are read and written by the DEM cloud"
           " layer (DEMCloud), not by " << c.name() << abort(FatalError);
    static const contactSlots none;
    return none;
}

//- The DEM state of the engine's particle i (DEMCloud)
template<class CloudType>
inline auto stateOf
(
    const CloudType& c,
    const label i,
    demParcelState& s,
    int
) -> decltype(c.demStateOf(i, s))
{
    return c.demStateOf(i, s);
}

template<class CloudType>
inline void stateOf(const CloudType& c, const label, demParcelState&, long)
{
    slotsOf(c, 0L);
}

} // End namespace DEMParcelDetail
} // End namespace Foam


template<class ParcelType>
template<class CloudType>
void Foam::DEMParcel<ParcelType>::readFields(CloudType& c)
{
    using namespace DEMParcelDetail;

    ParcelType::readFields(c);

    const bool valid = c.size();
    const word time(c.db().time().timeName());

    // Spin and the engine's last forces; absent after a run with another
    // cloud: the parcels start without them, and say so
    const wordList vectors({"angularVelocity", "contactForce", "contactTorque"});
    List<vectorField> values(3);
    forAll(vectors, v)
    {
        if (present<IOField<vector>>(c, vectors[v]))
        {
            IOField<vector> f
            (
                c.fieldIOobject(vectors[v], IOobject::MUST_READ),
                valid
            );
            c.checkFieldIOobject(c, f);
            values[v].transfer(f);
        }
        else
        {
            if (returnReduce(c.size(), sumOp<label>()))
            {
                Info<< "    No " << vectors[v] << " in " << time
                    << ": parcels start with zero " << vectors[v] << endl;
            }
            values[v].setSize(c.size(), Zero);
        }
    }

    // Contacts: the partner, then one field-field per declared slot
    const contactSlots& slots = slotsOf(c, 0);
    const bool haveContacts =
        present<labelFieldCompactIOField>(c, "demContactPartner");
    if (!haveContacts && returnReduce(c.size(), sumOp<label>()))
    {
        Info<< "    No demContact fields in " << time
            << ": parcels start without contact histories" << endl;
    }

    autoPtr<labelFieldCompactIOField> partner;
    autoPtr<vectorFieldCompactIOField> faceCentre;
    PtrList<scalarFieldCompactIOField> scalarSlots(slots.slots().size());
    PtrList<vectorFieldCompactIOField> vectorSlots(slots.slots().size());

    if (haveContacts)
    {
        partner.reset
        (
            new labelFieldCompactIOField
            (
                c.fieldIOobject("demContactPartner", IOobject::MUST_READ),
                valid
            )
        );
        c.checkFieldFieldIOobject(c, partner());
        faceCentre.reset
        (
            new vectorFieldCompactIOField
            (
                c.fieldIOobject("demContactFaceCentre", IOobject::MUST_READ),
                valid
            )
        );
        c.checkFieldFieldIOobject(c, faceCentre());

        forAll(slots.slots(), si)
        {
            const contactSlots::slot& s = slots.slots()[si];
            const word name(contactSlots::fieldName(s));
            if (s.isVector)
            {
                readIfPresent(c, name, valid, vectorSlots, si);
            }
            else
            {
                readIfPresent(c, name, valid, scalarSlots, si);
            }
            if
            (
                !vectorSlots.set(si) && !scalarSlots.set(si)
             && returnReduce(c.size(), sumOp<label>())
            )
            {
                Info<< "    No " << name << " in " << time
                    << ": the contacts start with zero " << s.name
                    << " (" << s.owner << ")" << endl;
            }
        }
    }

    const labelUList& vectorOffsets = slots.vectorOffsets();
    label i = 0;
    for (DEMParcel<ParcelType>& p : c)
    {
        p.state_.reset(new demParcelState());
        demParcelState& st = p.state_();
        st.angularVelocity = values[0][i];
        st.contactForce = values[1][i];
        st.contactTorque = values[2][i];

        if (haveContacts && partner()[i].size())
        {
            const label n = partner()[i].size()/2;
            bool consistent =
                partner()[i].size() == 2*n && faceCentre()[i].size() == n;
            forAll(slots.slots(), si)
            {
                if (vectorSlots.set(si))
                {
                    consistent = consistent && vectorSlots[si][i].size() == n;
                }
                if (scalarSlots.set(si))
                {
                    consistent = consistent && scalarSlots[si][i].size() == n;
                }
            }
            if (!consistent)
            {
                FatalErrorInFunction
                    << "Inconsistent demContact fields of parcel " << i
                    << " in " << c.db().time().timePath()
                    << exit(FatalError);
            }

            contactRecords& r = st.contacts;
            r.setSize(n, slots.stride(), vectorOffsets);
            r.state = 0;
            for (label k = 0; k < n; ++k)
            {
                const label proc = partner()[i][2*k];
                r.partner[k] =
                    proc < 0
                  ? demIdentity(-1)
                  : makeIdentity(proc, partner()[i][2*k + 1]);
                r.faceCentre[k] = faceCentre()[i][k];
                scalar* b = r.stateOf(k);
                forAll(slots.slots(), si)
                {
                    const label o = slots.slots()[si].offset;
                    if (vectorSlots.set(si))
                    {
                        const vector& v = vectorSlots[si][i][k];
                        b[o] = v.x();
                        b[o + 1] = v.y();
                        b[o + 2] = v.z();
                    }
                    else if (scalarSlots.set(si))
                    {
                        b[o] = scalarSlots[si][i][k];
                    }
                }
            }

            // This parcel's entries are copied: free them now, so that the
            // records are not held twice while the cloud is read
            partner()[i].clear();
            faceCentre()[i].clear();
            forAll(slots.slots(), si)
            {
                if (vectorSlots.set(si))
                {
                    vectorSlots[si][i].clear();
                }
                if (scalarSlots.set(si))
                {
                    scalarSlots[si][i].clear();
                }
            }
        }
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::DEMParcel<ParcelType>::writeFields(const CloudType& c)
{
    using namespace DEMParcelDetail;

    ParcelType::writeFields(c);

    const label np = c.size();
    const bool valid = np;
    const contactSlots& slots = slotsOf(c, 0);

    IOField<vector> angularVelocity
    (
        c.fieldIOobject("angularVelocity", IOobject::NO_READ),
        np
    );
    IOField<vector> contactForce
    (
        c.fieldIOobject("contactForce", IOobject::NO_READ),
        np
    );
    IOField<vector> contactTorque
    (
        c.fieldIOobject("contactTorque", IOobject::NO_READ),
        np
    );
    labelFieldCompactIOField partner
    (
        c.fieldIOobject("demContactPartner", IOobject::NO_READ),
        np
    );
    vectorFieldCompactIOField faceCentre
    (
        c.fieldIOobject("demContactFaceCentre", IOobject::NO_READ),
        np
    );
    PtrList<scalarFieldCompactIOField> scalarSlots(slots.slots().size());
    PtrList<vectorFieldCompactIOField> vectorSlots(slots.slots().size());
    forAll(slots.slots(), si)
    {
        const contactSlots::slot& s = slots.slots()[si];
        const IOobject io
        (
            c.fieldIOobject(contactSlots::fieldName(s), IOobject::NO_READ)
        );
        if (s.isVector)
        {
            vectorSlots.set(si, new vectorFieldCompactIOField(io, np));
        }
        else
        {
            scalarSlots.set(si, new scalarFieldCompactIOField(io, np));
        }
    }

    demParcelState engineState;
    label i = 0;
    for (const DEMParcel<ParcelType>& p : c)
    {
        // Off the engine (arrived this step), or from it
        const demParcelState* st = p.state_.get();
        if (!st && p.demIndex_ >= 0)
        {
            stateOf(c, p.demIndex_, engineState, 0);
            st = &engineState;
        }
        const contactRecords* r = st ? &st->contacts : nullptr;
        const label n = r ? r->size() : 0;
        angularVelocity[i] = st ? st->angularVelocity : Zero;
        contactForce[i] = st ? st->contactForce : Zero;
        contactTorque[i] = st ? st->contactTorque : Zero;

        partner[i].setSize(2*n);
        faceCentre[i].setSize(n);
        forAll(slots.slots(), si)
        {
            if (vectorSlots.set(si))
            {
                vectorSlots[si][i].setSize(n);
            }
            else
            {
                scalarSlots[si][i].setSize(n);
            }
        }
        for (label k = 0; k < n; ++k)
        {
            const demIdentity id = r->partner[k];
            partner[i][2*k] = contactRecords::isWall(id) ? -1 : identityProc(id);
            partner[i][2*k + 1] =
                contactRecords::isWall(id) ? -1 : identityIndex(id);
            faceCentre[i][k] = r->faceCentre[k];
            const scalar* b = r->stateOf(k);
            forAll(slots.slots(), si)
            {
                const label o = slots.slots()[si].offset;
                if (vectorSlots.set(si))
                {
                    vectorSlots[si][i][k] = vector(b[o], b[o + 1], b[o + 2]);
                }
                else
                {
                    scalarSlots[si][i][k] = b[o];
                }
            }
        }
        ++i;
    }

    angularVelocity.write(valid);
    contactForce.write(valid);
    contactTorque.write(valid);
    partner.write(valid);
    faceCentre.write(valid);
    forAll(slots.slots(), si)
    {
        if (vectorSlots.set(si))
        {
            vectorSlots[si].write(valid);
        }
        else
        {
            scalarSlots[si].write(valid);
        }
    }
}


template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const DEMParcel<ParcelType>& p
)
{
    os  << static_cast<const ParcelType&>(p) << token::SPACE
        << p.displacement_ << token::SPACE << label(p.state_.valid());
    if (p.state_.valid())
    {
        os << token::SPACE << p.state_();
    }

    os.check(FUNCTION_NAME);
    return os;
}
